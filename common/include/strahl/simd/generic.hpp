// strahl/simd.hpp, part 2: the fallback, plain arrays and one loop per operation, for every N (always
// compiled; the portable preset uses it for N = 8 and 16). The same bits as the intrinsics.
#pragma once
#include "strahl/simd/base.hpp"

namespace strahl::simd {

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

}  // namespace strahl::simd
