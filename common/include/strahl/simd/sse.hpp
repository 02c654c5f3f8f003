// strahl/simd.hpp, part 3: N = 4 on SSE2 (SSE4.1 for select where enabled), where the compiler flags enable it.
#pragma once
#include "strahl/simd/base.hpp"

namespace strahl::simd {

#if defined(__SSE2__)
// ---- N = 4: SSE2 (SSE4.1 for select where enabled) ------------------------------------------------------------

template <> struct vmask<4, true> {
    static constexpr int size = 4;
    __m128 m = _mm_setzero_ps();  // each lane all ones (true) or all zeros
    vmask() = default;
    vmask(__m128 r) : m(r) {}
    explicit vmask(bool b) : m(_mm_castsi128_ps(_mm_set1_epi32(-int(b)))) {}
    bool operator[](int i) const { return (_mm_movemask_ps(m) >> i) & 1; }
};

template <> struct alignas(16) vfloat<4, true> {
    static constexpr int size = 4;
    __m128 m = _mm_setzero_ps();
    vfloat() = default;
    vfloat(__m128 r) : m(r) {}
    explicit vfloat(float x) : m(_mm_set1_ps(x)) {}
    static vfloat load(const float* p) { return _mm_load_ps(p); }
    static vfloat loadu(const float* p) { return _mm_loadu_ps(p); }
    void store(float* p) const { _mm_store_ps(p, m); }
    void storeu(float* p) const { _mm_storeu_ps(p, m); }
    float operator[](int i) const { alignas(16) float t[4]; store(t); return t[i]; }
    void set(int i, float x) { alignas(16) float t[4]; store(t); t[i] = x; m = _mm_load_ps(t); }
};

template <> struct alignas(16) vint<4, true> {
    static constexpr int size = 4;
    __m128i m = _mm_setzero_si128();
    vint() = default;
    vint(__m128i r) : m(r) {}
    explicit vint(std::int32_t x) : m(_mm_set1_epi32(x)) {}
    static vint load(const std::int32_t* p) { return _mm_load_si128(reinterpret_cast<const __m128i*>(p)); }
    static vint loadu(const std::int32_t* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); }
    void store(std::int32_t* p) const { _mm_store_si128(reinterpret_cast<__m128i*>(p), m); }
    void storeu(std::int32_t* p) const { _mm_storeu_si128(reinterpret_cast<__m128i*>(p), m); }
    std::int32_t operator[](int i) const { alignas(16) std::int32_t t[4]; store(t); return t[i]; }
    void set(int i, std::int32_t x) { alignas(16) std::int32_t t[4]; store(t); t[i] = x; m = load(t).m; }
};

inline float4 operator+(float4 a, float4 b) { return _mm_add_ps(a.m, b.m); }
inline float4 operator-(float4 a, float4 b) { return _mm_sub_ps(a.m, b.m); }
inline float4 operator*(float4 a, float4 b) { return _mm_mul_ps(a.m, b.m); }
inline float4 operator/(float4 a, float4 b) { return _mm_div_ps(a.m, b.m); }
inline float4 operator-(float4 a) { return _mm_xor_ps(a.m, _mm_set1_ps(-0.0f)); }  // flips the sign bit, as -x
inline float4 min(float4 a, float4 b) { return _mm_min_ps(a.m, b.m); }
inline float4 sqrt(float4 a) { return _mm_sqrt_ps(a.m); }  // correctly rounded, as std::sqrt
inline float4 max(float4 a, float4 b) { return _mm_max_ps(a.m, b.m); }
#if defined(__FMA__)
inline float4 fmadd(float4 a, float4 b, float4 c) { return _mm_fmadd_ps(a.m, b.m, c.m); }
#else
inline float4 fmadd(float4 a, float4 b, float4 c) { return detail::fma_lanes(a, b, c); }
#endif

inline mask4 operator<(float4 a, float4 b) { return _mm_cmplt_ps(a.m, b.m); }
inline mask4 operator<=(float4 a, float4 b) { return _mm_cmple_ps(a.m, b.m); }
inline mask4 operator==(float4 a, float4 b) { return _mm_cmpeq_ps(a.m, b.m); }
inline mask4 operator!=(float4 a, float4 b) { return _mm_cmpneq_ps(a.m, b.m); }  // unordered: true with NaN
#if defined(__SSE4_1__)
inline float4 select(mask4 m, float4 a, float4 b) { return _mm_blendv_ps(b.m, a.m, m.m); }
#else
inline float4 select(mask4 m, float4 a, float4 b) {
    return _mm_or_ps(_mm_and_ps(m.m, a.m), _mm_andnot_ps(m.m, b.m));
}
#endif
inline float reduce_min(float4 a) {
    const __m128 h = _mm_min_ps(a.m, _mm_movehl_ps(a.m, a.m));  // lanes 0, 1: min(a0, a2), min(a1, a3)
    return _mm_cvtss_f32(_mm_min_ss(h, _mm_shuffle_ps(h, h, _MM_SHUFFLE(1, 1, 1, 1))));
}
inline float reduce_max(float4 a) {
    const __m128 h = _mm_max_ps(a.m, _mm_movehl_ps(a.m, a.m));
    return _mm_cvtss_f32(_mm_max_ss(h, _mm_shuffle_ps(h, h, _MM_SHUFFLE(1, 1, 1, 1))));
}

inline mask4 operator&(mask4 a, mask4 b) { return _mm_and_ps(a.m, b.m); }
inline mask4 operator|(mask4 a, mask4 b) { return _mm_or_ps(a.m, b.m); }
inline mask4 operator^(mask4 a, mask4 b) { return _mm_xor_ps(a.m, b.m); }
inline mask4 operator~(mask4 a) { return _mm_xor_ps(a.m, mask4(true).m); }
inline unsigned movemask(mask4 a) { return unsigned(_mm_movemask_ps(a.m)); }
inline mask4 from_bits4(unsigned b) {
    const __m128i bit = _mm_setr_epi32(1, 2, 4, 8);
    return _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(int(b)), bit), bit));
}

inline int4 operator+(int4 a, int4 b) { return _mm_add_epi32(a.m, b.m); }
inline int4 operator-(int4 a, int4 b) { return _mm_sub_epi32(a.m, b.m); }
inline mask4 operator<(int4 a, int4 b) { return _mm_castsi128_ps(_mm_cmplt_epi32(a.m, b.m)); }
inline mask4 operator==(int4 a, int4 b) { return _mm_castsi128_ps(_mm_cmpeq_epi32(a.m, b.m)); }
inline mask4 operator!=(int4 a, int4 b) { return ~(a == b); }
inline int4 as_int(float4 a) { return _mm_castps_si128(a.m); }
inline float4 as_float(int4 a) { return _mm_castsi128_ps(a.m); }
inline float4 to_float(int4 a) { return _mm_cvtepi32_ps(a.m); }
inline int4 to_int(float4 a) { return _mm_cvttps_epi32(a.m); }
#endif  // __SSE2__

}  // namespace strahl::simd
