// strahl/simd.hpp, part 5: N = 16 on AVX-512F (masks in a mask register), where the compiler flags enable it.
#pragma once
#include "strahl/simd/base.hpp"

namespace strahl::simd {

#if defined(__AVX512F__)
// (GCC 12 warns falsely that its own AVX-512 intrinsics read an uninitialised value: GCC PR 105593.)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
// ---- N = 16: AVX-512F, masks in a mask register -------------------------------------------------------------

template <> struct vmask<16, true> {
    static constexpr int size = 16;
    __mmask16 m = 0;  // lane i in bit i
    vmask() = default;
    explicit vmask(__mmask16 r) : m(r) {}  // explicit, so that `mask16 m = true;` cannot mean lane 0 only
    explicit vmask(bool b) : m(b ? 0xffff : 0) {}
    bool operator[](int i) const { return (m >> i) & 1; }
};

template <> struct alignas(64) vfloat<16, true> {
    static constexpr int size = 16;
    __m512 m = _mm512_setzero_ps();
    vfloat() = default;
    vfloat(__m512 r) : m(r) {}
    explicit vfloat(float x) : m(_mm512_set1_ps(x)) {}
    static vfloat load(const float* p) { return _mm512_load_ps(p); }
    static vfloat loadu(const float* p) { return _mm512_loadu_ps(p); }
    void store(float* p) const { _mm512_store_ps(p, m); }
    void storeu(float* p) const { _mm512_storeu_ps(p, m); }
    float operator[](int i) const { alignas(64) float t[16]; store(t); return t[i]; }
    void set(int i, float x) { alignas(64) float t[16]; store(t); t[i] = x; m = _mm512_load_ps(t); }
};

template <> struct alignas(64) vint<16, true> {
    static constexpr int size = 16;
    __m512i m = _mm512_setzero_si512();
    vint() = default;
    vint(__m512i r) : m(r) {}
    explicit vint(std::int32_t x) : m(_mm512_set1_epi32(x)) {}
    static vint load(const std::int32_t* p) { return _mm512_load_si512(p); }
    static vint loadu(const std::int32_t* p) { return _mm512_loadu_si512(p); }
    void store(std::int32_t* p) const { _mm512_store_si512(p, m); }
    void storeu(std::int32_t* p) const { _mm512_storeu_si512(p, m); }
    std::int32_t operator[](int i) const { alignas(64) std::int32_t t[16]; store(t); return t[i]; }
    void set(int i, std::int32_t x) { alignas(64) std::int32_t t[16]; store(t); t[i] = x; m = load(t).m; }
};

inline float16 operator+(float16 a, float16 b) { return _mm512_add_ps(a.m, b.m); }
inline float16 operator-(float16 a, float16 b) { return _mm512_sub_ps(a.m, b.m); }
inline float16 operator*(float16 a, float16 b) { return _mm512_mul_ps(a.m, b.m); }
inline float16 operator/(float16 a, float16 b) { return _mm512_div_ps(a.m, b.m); }
inline float16 operator-(float16 a) {  // AVX-512F has no float xor: flip the sign bit as an integer
    return _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(a.m), _mm512_set1_epi32(-0x7fffffff - 1)));
}
inline float16 min(float16 a, float16 b) { return _mm512_min_ps(a.m, b.m); }
inline float16 sqrt(float16 a) { return _mm512_sqrt_ps(a.m); }
inline float16 max(float16 a, float16 b) { return _mm512_max_ps(a.m, b.m); }
inline float16 fmadd(float16 a, float16 b, float16 c) { return _mm512_fmadd_ps(a.m, b.m, c.m); }

inline mask16 operator<(float16 a, float16 b) { return mask16(_mm512_cmp_ps_mask(a.m, b.m, _CMP_LT_OQ)); }
inline mask16 operator<=(float16 a, float16 b) { return mask16(_mm512_cmp_ps_mask(a.m, b.m, _CMP_LE_OQ)); }
inline mask16 operator==(float16 a, float16 b) { return mask16(_mm512_cmp_ps_mask(a.m, b.m, _CMP_EQ_OQ)); }
inline mask16 operator!=(float16 a, float16 b) { return mask16(_mm512_cmp_ps_mask(a.m, b.m, _CMP_NEQ_UQ)); }
inline float16 select(mask16 m, float16 a, float16 b) { return _mm512_mask_blend_ps(m.m, b.m, a.m); }
namespace detail {
inline float8 low_half(float16 a) { return _mm512_castps512_ps256(a.m); }
inline float8 high_half(float16 a) { return _mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(a.m), 1)); }
}  // namespace detail
inline float reduce_min(float16 a) { return reduce_min(min(detail::low_half(a), detail::high_half(a))); }
inline float reduce_max(float16 a) { return reduce_max(max(detail::low_half(a), detail::high_half(a))); }

inline mask16 operator&(mask16 a, mask16 b) { return mask16(__mmask16(a.m & b.m)); }
inline mask16 operator|(mask16 a, mask16 b) { return mask16(__mmask16(a.m | b.m)); }
inline mask16 operator^(mask16 a, mask16 b) { return mask16(__mmask16(a.m ^ b.m)); }
inline mask16 operator~(mask16 a) { return mask16(__mmask16(~a.m)); }
inline unsigned movemask(mask16 a) { return a.m; }
inline mask16 from_bits16(unsigned b) { return mask16(__mmask16(b)); }

inline int16 operator+(int16 a, int16 b) { return _mm512_add_epi32(a.m, b.m); }
inline int16 operator-(int16 a, int16 b) { return _mm512_sub_epi32(a.m, b.m); }
inline mask16 operator<(int16 a, int16 b) { return mask16(_mm512_cmplt_epi32_mask(a.m, b.m)); }
inline mask16 operator==(int16 a, int16 b) { return mask16(_mm512_cmpeq_epi32_mask(a.m, b.m)); }
inline mask16 operator!=(int16 a, int16 b) { return mask16(_mm512_cmpneq_epi32_mask(a.m, b.m)); }
inline int16 as_int(float16 a) { return _mm512_castps_si512(a.m); }
inline float16 as_float(int16 a) { return _mm512_castsi512_ps(a.m); }
inline float16 to_float(int16 a) { return _mm512_cvtepi32_ps(a.m); }
inline int16 to_int(float16 a) { return _mm512_cvttps_epi32(a.m); }
#pragma GCC diagnostic pop
#endif  // __AVX512F__

}  // namespace strahl::simd
