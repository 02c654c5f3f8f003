// strahl/simd.hpp, part 1: which widths are native in this build, the types, the case N = 1, helpers.
// Included through strahl/simd.hpp, whose comment states the rounding promise every part keeps.
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

}  // namespace strahl::simd
