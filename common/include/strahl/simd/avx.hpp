// strahl/simd.hpp, part 4: N = 8 on AVX (AVX2 for integer lanes, else the SSE2 operation on each half), where
// the compiler flags enable it.
#pragma once
#include "strahl/simd/sse.hpp"

namespace strahl::simd {

#if defined(__AVX__)
// ---- N = 8: AVX (AVX2 for integer lanes, else the SSE2 operation on each 128-bit half) ----------------------

namespace detail {
#if defined(__AVX2__)
inline __m256i add32(__m256i a, __m256i b) { return _mm256_add_epi32(a, b); }
inline __m256i sub32(__m256i a, __m256i b) { return _mm256_sub_epi32(a, b); }
inline __m256i cmpgt32(__m256i a, __m256i b) { return _mm256_cmpgt_epi32(a, b); }
inline __m256i cmpeq32(__m256i a, __m256i b) { return _mm256_cmpeq_epi32(a, b); }
#else
template <class Op> __m256i halves(__m256i a, __m256i b, Op op) {
    return _mm256_setr_m128i(op(_mm256_castsi256_si128(a), _mm256_castsi256_si128(b)),
                             op(_mm256_extractf128_si256(a, 1), _mm256_extractf128_si256(b, 1)));
}
inline __m256i add32(__m256i a, __m256i b) {
    return halves(a, b, [](__m128i x, __m128i y) { return _mm_add_epi32(x, y); });
}
inline __m256i sub32(__m256i a, __m256i b) {
    return halves(a, b, [](__m128i x, __m128i y) { return _mm_sub_epi32(x, y); });
}
inline __m256i cmpgt32(__m256i a, __m256i b) {
    return halves(a, b, [](__m128i x, __m128i y) { return _mm_cmpgt_epi32(x, y); });
}
inline __m256i cmpeq32(__m256i a, __m256i b) {
    return halves(a, b, [](__m128i x, __m128i y) { return _mm_cmpeq_epi32(x, y); });
}
#endif
}  // namespace detail

template <> struct vmask<8, true> {
    static constexpr int size = 8;
    __m256 m = _mm256_setzero_ps();  // each lane all ones (true) or all zeros
    vmask() = default;
    vmask(__m256 r) : m(r) {}
    explicit vmask(bool b) : m(_mm256_castsi256_ps(_mm256_set1_epi32(-int(b)))) {}
    bool operator[](int i) const { return (_mm256_movemask_ps(m) >> i) & 1; }
};

template <> struct alignas(32) vfloat<8, true> {
    static constexpr int size = 8;
    __m256 m = _mm256_setzero_ps();
    vfloat() = default;
    vfloat(__m256 r) : m(r) {}
    explicit vfloat(float x) : m(_mm256_set1_ps(x)) {}
    static vfloat load(const float* p) { return _mm256_load_ps(p); }
    static vfloat loadu(const float* p) { return _mm256_loadu_ps(p); }
    void store(float* p) const { _mm256_store_ps(p, m); }
    void storeu(float* p) const { _mm256_storeu_ps(p, m); }
    float operator[](int i) const { alignas(32) float t[8]; store(t); return t[i]; }
    void set(int i, float x) { alignas(32) float t[8]; store(t); t[i] = x; m = _mm256_load_ps(t); }
};

template <> struct alignas(32) vint<8, true> {
    static constexpr int size = 8;
    __m256i m = _mm256_setzero_si256();
    vint() = default;
    vint(__m256i r) : m(r) {}
    explicit vint(std::int32_t x) : m(_mm256_set1_epi32(x)) {}
    static vint load(const std::int32_t* p) { return _mm256_load_si256(reinterpret_cast<const __m256i*>(p)); }
    static vint loadu(const std::int32_t* p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)); }
    void store(std::int32_t* p) const { _mm256_store_si256(reinterpret_cast<__m256i*>(p), m); }
    void storeu(std::int32_t* p) const { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), m); }
    std::int32_t operator[](int i) const { alignas(32) std::int32_t t[8]; store(t); return t[i]; }
    void set(int i, std::int32_t x) { alignas(32) std::int32_t t[8]; store(t); t[i] = x; m = load(t).m; }
};

inline float8 operator+(float8 a, float8 b) { return _mm256_add_ps(a.m, b.m); }
inline float8 operator-(float8 a, float8 b) { return _mm256_sub_ps(a.m, b.m); }
inline float8 operator*(float8 a, float8 b) { return _mm256_mul_ps(a.m, b.m); }
inline float8 operator/(float8 a, float8 b) { return _mm256_div_ps(a.m, b.m); }
inline float8 operator-(float8 a) { return _mm256_xor_ps(a.m, _mm256_set1_ps(-0.0f)); }
inline float8 min(float8 a, float8 b) { return _mm256_min_ps(a.m, b.m); }
inline float8 sqrt(float8 a) { return _mm256_sqrt_ps(a.m); }
inline float8 max(float8 a, float8 b) { return _mm256_max_ps(a.m, b.m); }
#if defined(__FMA__)
inline float8 fmadd(float8 a, float8 b, float8 c) { return _mm256_fmadd_ps(a.m, b.m, c.m); }
#else
inline float8 fmadd(float8 a, float8 b, float8 c) { return detail::fma_lanes(a, b, c); }
#endif

inline mask8 operator<(float8 a, float8 b) { return _mm256_cmp_ps(a.m, b.m, _CMP_LT_OQ); }
inline mask8 operator<=(float8 a, float8 b) { return _mm256_cmp_ps(a.m, b.m, _CMP_LE_OQ); }
inline mask8 operator==(float8 a, float8 b) { return _mm256_cmp_ps(a.m, b.m, _CMP_EQ_OQ); }
inline mask8 operator!=(float8 a, float8 b) { return _mm256_cmp_ps(a.m, b.m, _CMP_NEQ_UQ); }
inline float8 select(mask8 m, float8 a, float8 b) { return _mm256_blendv_ps(b.m, a.m, m.m); }
namespace detail {
inline float4 low_half(float8 a) { return _mm256_castps256_ps128(a.m); }
inline float4 high_half(float8 a) { return _mm256_extractf128_ps(a.m, 1); }
}  // namespace detail
inline float reduce_min(float8 a) { return reduce_min(min(detail::low_half(a), detail::high_half(a))); }
inline float reduce_max(float8 a) { return reduce_max(max(detail::low_half(a), detail::high_half(a))); }

inline mask8 operator&(mask8 a, mask8 b) { return _mm256_and_ps(a.m, b.m); }
inline mask8 operator|(mask8 a, mask8 b) { return _mm256_or_ps(a.m, b.m); }
inline mask8 operator^(mask8 a, mask8 b) { return _mm256_xor_ps(a.m, b.m); }
inline mask8 operator~(mask8 a) { return _mm256_xor_ps(a.m, mask8(true).m); }
inline unsigned movemask(mask8 a) { return unsigned(_mm256_movemask_ps(a.m)); }
inline mask8 from_bits8(unsigned b) {
    const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    const __m256 set = _mm256_and_ps(_mm256_castsi256_ps(_mm256_set1_epi32(int(b))), _mm256_castsi256_ps(bit));
    return _mm256_castsi256_ps(detail::cmpeq32(_mm256_castps_si256(set), bit));
}

inline int8 operator+(int8 a, int8 b) { return detail::add32(a.m, b.m); }
inline int8 operator-(int8 a, int8 b) { return detail::sub32(a.m, b.m); }
inline mask8 operator<(int8 a, int8 b) { return _mm256_castsi256_ps(detail::cmpgt32(b.m, a.m)); }
inline mask8 operator==(int8 a, int8 b) { return _mm256_castsi256_ps(detail::cmpeq32(a.m, b.m)); }
inline mask8 operator!=(int8 a, int8 b) { return ~(a == b); }
inline int8 as_int(float8 a) { return _mm256_castps_si256(a.m); }
inline float8 as_float(int8 a) { return _mm256_castsi256_ps(a.m); }
inline float8 to_float(int8 a) { return _mm256_cvtepi32_ps(a.m); }
inline int8 to_int(float8 a) { return _mm256_cvttps_epi32(a.m); }
#endif  // __AVX__

}  // namespace strahl::simd
