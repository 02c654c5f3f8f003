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
//
// Parts, one header per instruction set under strahl/simd/: base.hpp (the types, N = 1), generic.hpp (the
// fallback), sse.hpp, avx.hpp, avx512.hpp; the operations derived from them for every backend follow here.
#pragma once
#include "strahl/simd/base.hpp"
#include "strahl/simd/generic.hpp"
#include "strahl/simd/sse.hpp"
#include "strahl/simd/avx.hpp"
#include "strahl/simd/avx512.hpp"

namespace strahl::simd {

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
// N unsigned bytes (p[0] .. p[N - 1]) as float lanes, exactly (every byte is a float): chapter 13's
// quantised nodes keep their planes as bytes.
template <int N> vfloat<N> bytes_to_float(const std::uint8_t* p) {
#if defined(__AVX2__)
    if constexpr (native<N> && N == 8)
        return vfloat<N>(_mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)))));
#endif
#if defined(__AVX512F__)
    if constexpr (native<N> && N == 16)
        return vfloat<N>(_mm512_cvtepi32_ps(_mm512_cvtepu8_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)))));
#endif
    alignas(64) float f[N];
    for (int i = 0; i < N; ++i) f[i] = float(p[i]);
    return vfloat<N>::load(f);
}
template <int N, bool B> bool any(vmask<N, B> m) { return movemask(m) != 0; }
template <int N, bool B> bool all(vmask<N, B> m) { return movemask(m) == detail::lane_bits(N); }
template <int N, bool B> bool none(vmask<N, B> m) { return movemask(m) == 0; }
template <int N, bool B> int popcount(vmask<N, B> m) { return std::popcount(movemask(m)); }

}  // namespace strahl::simd
