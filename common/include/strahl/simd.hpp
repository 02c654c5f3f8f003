// A thin SIMD layer: vfloat<N>, vint<N> (int32 lanes) and vmask<N> for N = 4, 8, 16 (float4 ... mask16), the
// vocabulary of chapter 13's wide BVH (one ray against the 4, 8 or 16 boxes of a node, against 4 or 8 triangles)
// and of chapter 12's ray packets.
//
// The rounding promise: every arithmetic operation rounds on each lane exactly like the scalar C++ operation
// (IEEE single precision, round to nearest; no approximations such as rcp or rsqrt, / is a true division), and
// fmadd/fmsub round once, bit for bit like std::fma. So SIMD code gives the answers of scalar code that does the
// same operations in the same order, bit for bit (the project compiles with -ffp-contract=off, never -ffast-math).
// Only which NaN a NaN result is (sign, payload) is not promised. min, max and select move data, keep every bit:
// min(a, b) = a < b ? a : b, the rule of x86's minps, so a NaN in either operand, or -0 against +0, gives the
// SECOND operand (std::min(a, b) = b < a ? b : a is not the same!); max(a, b) = a > b ? a : b likewise.
//
// Backends: vfloat<N> is vfloat<N, native<N>>. vfloat<N, true> wraps intrinsics where the compiler flags enable
// them: N = 4 with SSE2 (SSE4.1's blend for select), N = 8 with AVX (integer lanes with AVX2, else as two SSE2
// halves), N = 16 with AVX-512F (masks are __mmask16); fmadd with FMA where enabled, else std::fma per lane.
// vfloat<N, false> (generic_vfloat<N>) is the scalar fallback, always compiled: a plain array and one loop per
// operation, for every N. It gives the same bits; the portable preset (plain x86-64, SSE2) uses it for N = 8, 16.
//
// All operations are free functions of strahl::simd. Constructing from a scalar broadcasts it and is explicit
// (float8(1.0f)), so every backend compiles the same code. min, max, fmadd, fmsub, select, any, all and none also
// exist for plain float and bool (the case N = 1), so one templated slab test serves a ray and a wide node.
#pragma once
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace strahl::simd {

// ---- Which widths are backed by intrinsics in this build ------------------------------------------------------

template <int N> inline constexpr bool native = false;
#if defined(__SSE2__)
template <> inline constexpr bool native<4> = true;
#endif
#if defined(__AVX__)
template <> inline constexpr bool native<8> = true;
#endif
#if defined(__AVX512F__)
template <> inline constexpr bool native<16> = true;
#endif

// ---- The types -------------------------------------------------------------------------------------------------

template <int N, bool Native = native<N>> struct vfloat;
template <int N, bool Native = native<N>> struct vint;
template <int N, bool Native = native<N>> struct vmask;

template <int N> using generic_vfloat = vfloat<N, false>;
template <int N> using generic_vint = vint<N, false>;
template <int N> using generic_vmask = vmask<N, false>;

using float4 = vfloat<4>;
using float8 = vfloat<8>;
using float16 = vfloat<16>;
using int4 = vint<4>;
using int8 = vint<8>;
using int16 = vint<16>;
using mask4 = vmask<4>;
using mask8 = vmask<8>;
using mask16 = vmask<16>;

// ---- N = 1: the same names for plain float and bool ----------------------------------------------------------

inline float min(float a, float b) { return a < b ? a : b; }
inline float max(float a, float b) { return a > b ? a : b; }
inline float fmadd(float a, float b, float c) { return std::fma(a, b, c); }
inline float fmsub(float a, float b, float c) { return std::fma(a, b, -c); }
inline float select(bool m, float a, float b) { return m ? a : b; }
inline std::int32_t select(bool m, std::int32_t a, std::int32_t b) { return m ? a : b; }
inline bool any(bool m) { return m; }
inline bool all(bool m) { return m; }
inline bool none(bool m) { return !m; }

namespace detail {
inline constexpr std::uint32_t lane_bits(int n) { return n == 32 ? ~0u : (1u << n) - 1; }
inline bool aligned(const void* p, std::size_t a) { return reinterpret_cast<std::uintptr_t>(p) % a == 0; }

// fmadd lane by lane with std::fma (one rounding), where no FMA instruction is enabled.
template <class V> V fma_lanes(V a, V b, V c) {
    alignas(64) float x[V::size], y[V::size], z[V::size];
    a.storeu(x);
    b.storeu(y);
    c.storeu(z);
    for (int i = 0; i < V::size; ++i) x[i] = std::fma(x[i], y[i], z[i]);
    return V::loadu(x);
}

// The fallback's one loop: r, with lane i set to f(i).
template <class V, class F> V each(V r, F f) {
    for (int i = 0; i < V::size; ++i) r.v[i] = f(i);
    return r;
}
template <int N, class F> vmask<N, false> each_mask(F f) {
    vmask<N, false> r;
    for (int i = 0; i < N; ++i) r.bits |= std::uint32_t(f(i)) << i;
    return r;
}
}  // namespace detail

// ---- The fallback: plain arrays, every N ------------------------------------------------------------------------

template <int N> struct vmask<N, false> {
    static_assert(N <= 32 && std::has_single_bit(unsigned(N)), "N: a power of two, at most 32");
    static constexpr int size = N;
    std::uint32_t bits = 0;  // lane i in bit i
    vmask() = default;
    explicit vmask(bool b) : bits(b ? detail::lane_bits(N) : 0) {}
    bool operator[](int i) const { return (bits >> i) & 1; }
};

template <int N> struct alignas(4 * N) vfloat<N, false> {
    static constexpr int size = N;
    std::array<float, N> v{};
    vfloat() = default;
    explicit vfloat(float x) { v.fill(x); }
    static vfloat load(const float* p) { assert(detail::aligned(p, alignof(vfloat))); return loadu(p); }
    static vfloat loadu(const float* p) { vfloat r; for (int i = 0; i < N; ++i) r.v[i] = p[i]; return r; }
    void store(float* p) const { assert(detail::aligned(p, alignof(vfloat))); storeu(p); }
    void storeu(float* p) const { for (int i = 0; i < N; ++i) p[i] = v[i]; }
    float operator[](int i) const { return v[i]; }
    void set(int i, float x) { v[i] = x; }
};

template <int N> struct alignas(4 * N) vint<N, false> {
    static constexpr int size = N;
    std::array<std::int32_t, N> v{};
    vint() = default;
    explicit vint(std::int32_t x) { v.fill(x); }
    static vint load(const std::int32_t* p) { assert(detail::aligned(p, alignof(vint))); return loadu(p); }
    static vint loadu(const std::int32_t* p) { vint r; for (int i = 0; i < N; ++i) r.v[i] = p[i]; return r; }
    void store(std::int32_t* p) const { assert(detail::aligned(p, alignof(vint))); storeu(p); }
    void storeu(std::int32_t* p) const { for (int i = 0; i < N; ++i) p[i] = v[i]; }
    std::int32_t operator[](int i) const { return v[i]; }
    void set(int i, std::int32_t x) { v[i] = x; }
};

// Arithmetic, lane by lane: exactly the scalar operations.
template <int N> generic_vfloat<N> operator+(generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each(a, [&](int i) { return a[i] + b[i]; });
}
template <int N> generic_vfloat<N> operator-(generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each(a, [&](int i) { return a[i] - b[i]; });
}
template <int N> generic_vfloat<N> operator*(generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each(a, [&](int i) { return a[i] * b[i]; });
}
template <int N> generic_vfloat<N> operator/(generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each(a, [&](int i) { return a[i] / b[i]; });
}
template <int N> generic_vfloat<N> operator-(generic_vfloat<N> a) {
    return detail::each(a, [&](int i) { return -a[i]; });
}
template <int N> generic_vfloat<N> min(generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each(a, [&](int i) { return min(a[i], b[i]); });
}
template <int N> generic_vfloat<N> max(generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each(a, [&](int i) { return max(a[i], b[i]); });
}
template <int N> generic_vfloat<N> fmadd(generic_vfloat<N> a, generic_vfloat<N> b, generic_vfloat<N> c) {
    return detail::fma_lanes(a, b, c);
}
template <int N> generic_vfloat<N> sqrt(generic_vfloat<N> a) {
    return detail::each(a, [&](int i) { return std::sqrt(a[i]); });
}

// Comparisons (IEEE: false where a lane is NaN, except !=), and select(m, a, b): a where m is set, else b.
template <int N> generic_vmask<N> operator<(generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each_mask<N>([&](int i) { return a[i] < b[i]; });
}
template <int N> generic_vmask<N> operator<=(generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each_mask<N>([&](int i) { return a[i] <= b[i]; });
}
template <int N> generic_vmask<N> operator==(generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each_mask<N>([&](int i) { return a[i] == b[i]; });
}
template <int N> generic_vmask<N> operator!=(generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each_mask<N>([&](int i) { return a[i] != b[i]; });
}
template <int N> generic_vfloat<N> select(generic_vmask<N> m, generic_vfloat<N> a, generic_vfloat<N> b) {
    return detail::each(a, [&](int i) { return m[i] ? a[i] : b[i]; });
}

// Horizontal min and max, as a halving tree: lane i against lane i + N/2, ..., then lane 0 against lane 1.
// Every backend follows this order, so even with NaN or signed zeros the result is the same.
template <int N> float reduce_min(generic_vfloat<N> a) {
    for (int w = N / 2; w >= 1; w /= 2)
        for (int i = 0; i < w; ++i) a.v[i] = min(a.v[i], a.v[i + w]);
    return a.v[0];
}
template <int N> float reduce_max(generic_vfloat<N> a) {
    for (int w = N / 2; w >= 1; w /= 2)
        for (int i = 0; i < w; ++i) a.v[i] = max(a.v[i], a.v[i + w]);
    return a.v[0];
}

// Masks: bitwise logic and movemask (lane i in bit i).
template <int N> generic_vmask<N> operator&(generic_vmask<N> a, generic_vmask<N> b) { a.bits &= b.bits; return a; }
template <int N> generic_vmask<N> operator|(generic_vmask<N> a, generic_vmask<N> b) { a.bits |= b.bits; return a; }
template <int N> generic_vmask<N> operator^(generic_vmask<N> a, generic_vmask<N> b) { a.bits ^= b.bits; return a; }
template <int N> generic_vmask<N> operator~(generic_vmask<N> a) { a.bits ^= detail::lane_bits(N); return a; }
template <int N> unsigned movemask(generic_vmask<N> a) { return a.bits; }
// movemask's inverse: lane i true where bit i of b is set (bits from N on ignored).
template <int N> generic_vmask<N> from_bits_generic(unsigned b) { generic_vmask<N> r; r.bits = b & detail::lane_bits(N); return r; }

// Integer lanes: + and - wrap around (two's complement) as the hardware does; comparisons are signed.
template <int N> generic_vint<N> operator+(generic_vint<N> a, generic_vint<N> b) {
    return detail::each(a, [&](int i) { return std::int32_t(std::uint32_t(a[i]) + std::uint32_t(b[i])); });
}
template <int N> generic_vint<N> operator-(generic_vint<N> a, generic_vint<N> b) {
    return detail::each(a, [&](int i) { return std::int32_t(std::uint32_t(a[i]) - std::uint32_t(b[i])); });
}
template <int N> generic_vmask<N> operator<(generic_vint<N> a, generic_vint<N> b) {
    return detail::each_mask<N>([&](int i) { return a[i] < b[i]; });
}
template <int N> generic_vmask<N> operator==(generic_vint<N> a, generic_vint<N> b) {
    return detail::each_mask<N>([&](int i) { return a[i] == b[i]; });
}
template <int N> generic_vmask<N> operator!=(generic_vint<N> a, generic_vint<N> b) { return ~(a == b); }

// Between float and int lanes: as_int/as_float reinterpret the bits; to_float rounds to nearest like
// static_cast<float>; to_int truncates like static_cast<int32_t>, and gives INT32_MIN where that is undefined
// (NaN, out of range), as cvttps2dq does.
template <int N> generic_vint<N> as_int(generic_vfloat<N> a) {
    return detail::each(generic_vint<N>(), [&](int i) { return std::bit_cast<std::int32_t>(a[i]); });
}
template <int N> generic_vfloat<N> as_float(generic_vint<N> a) {
    return detail::each(generic_vfloat<N>(), [&](int i) { return std::bit_cast<float>(a[i]); });
}
template <int N> generic_vfloat<N> to_float(generic_vint<N> a) {
    return detail::each(generic_vfloat<N>(), [&](int i) { return float(a[i]); });
}
template <int N> generic_vint<N> to_int(generic_vfloat<N> a) {
    return detail::each(generic_vint<N>(), [&](int i) {
        return a[i] >= -0x1p31f && a[i] < 0x1p31f ? std::int32_t(a[i]) : std::int32_t(-0x7fffffff - 1);
    });
}

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

// ---- Derived from the above, the same for every backend ---------------------------------------------------------

template <int N, bool B> vmask<N, B> operator>(vfloat<N, B> a, vfloat<N, B> b) { return b < a; }
template <int N, bool B> vmask<N, B> operator>=(vfloat<N, B> a, vfloat<N, B> b) { return b <= a; }
template <int N, bool B> vmask<N, B> operator>(vint<N, B> a, vint<N, B> b) { return b < a; }
template <int N, bool B> vmask<N, B> operator<=(vint<N, B> a, vint<N, B> b) { return ~(b < a); }
template <int N, bool B> vmask<N, B> operator>=(vint<N, B> a, vint<N, B> b) { return ~(a < b); }
// a*b - c with one rounding (negating c is exact).
template <int N, bool B> vfloat<N, B> fmsub(vfloat<N, B> a, vfloat<N, B> b, vfloat<N, B> c) {
    return fmadd(a, b, -c);
}
template <int N, bool B> vint<N, B> select(vmask<N, B> m, vint<N, B> a, vint<N, B> b) {
    return as_int(select(m, as_float(a), as_float(b)));
}
// a & ~b (note: Intel's _mm_andnot_ps(a, b) is ~a & b).
template <int N, bool B> vmask<N, B> andnot(vmask<N, B> a, vmask<N, B> b) { return a & ~b; }
// movemask's inverse: the mask of N lanes whose lane i is bit i of b.
template <int N> vmask<N> from_bits(unsigned b) {
    if constexpr (!native<N>) return from_bits_generic<N>(b);
#if defined(__SSE2__)
    else if constexpr (N == 4) return from_bits4(b);
#endif
#if defined(__AVX__)
    else if constexpr (N == 8) return from_bits8(b);
#endif
#if defined(__AVX512F__)
    else if constexpr (N == 16) return from_bits16(b);
#endif
}
template <int N, bool B> bool any(vmask<N, B> m) { return movemask(m) != 0; }
template <int N, bool B> bool all(vmask<N, B> m) { return movemask(m) == detail::lane_bits(N); }
template <int N, bool B> bool none(vmask<N, B> m) { return movemask(m) == 0; }
template <int N, bool B> int popcount(vmask<N, B> m) { return std::popcount(movemask(m)); }

}  // namespace strahl::simd
