// Flush-to-zero and denormals-are-zero for the calls into Embree. Embree wants both on in every thread that
// traces (its documentation, and a warning in its verbose report); the course wants neither: they are set
// around Embree's calls only. MXCSR bit 15 is flush-to-zero (results that would be denormal become 0), bit 6
// denormals-are-zero (denormal inputs read as 0).
#pragma once
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace strahl {

// Sets both bits in this thread's MXCSR for its lifetime, then restores it.
class denormals_flushed {
public:
#if defined(__SSE__)
    static constexpr unsigned bits = (1u << 15) | (1u << 6);
    denormals_flushed() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | bits); }
    ~denormals_flushed() { _mm_setcsr(saved_); }
#else
    denormals_flushed() = default;
#endif
    denormals_flushed(const denormals_flushed&) = delete;
    denormals_flushed& operator=(const denormals_flushed&) = delete;

private:
    [[maybe_unused]] unsigned saved_ = 0;
};

// This thread's flush-to-zero and denormals-are-zero bits: both set (true) or not.
inline bool denormals_are_flushed() {
#if defined(__SSE__)
    return (_mm_getcsr() & denormals_flushed::bits) == denormals_flushed::bits;
#else
    return false;
#endif
}

}  // namespace strahl
