// What the SIMD layer's tests share (test_simd.cpp, test_simd_masks.cpp): the inputs, the lane-by-lane checks
// against scalar C++, and a slab test written once for float and vfloat.
#pragma once
#include <catch2/catch.hpp>
#include "strahl/simd.hpp"
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <type_traits>

namespace simd = strahl::simd;

namespace {

using i32 = std::int32_t;
using u32 = std::uint32_t;

const float inf = std::numeric_limits<float>::infinity();
const float qnan = std::numeric_limits<float>::quiet_NaN();

const float specials[] = {0.0f,       -0.0f,       inf,          -inf,         qnan,           -qnan,
                          std::bit_cast<float>(0x7fc01234u),         std::bit_cast<float>(0xffd0beefu),
                          0x1p-149f,  -0x1p-149f,  0x1.8p-130f,  0x1p-126f,    -0x1p-126f,     0x1.fffffep127f,
                          -0x1.fffffep127f, 1.0f,  -1.0f,        0.5f,         3.0f,           0x1.000002p0f,
                          1e30f,      -1e-30f,     16777216.0f,  -2147483648.0f};
constexpr int n_specials = int(std::size(specials));

bool same_bits(float x, float y) { return std::bit_cast<u32>(x) == std::bit_cast<u32>(y); }
// Bit for bit, except that any two NaNs count as equal.
bool same_value(float x, float y) { return same_bits(x, y) || (std::isnan(x) && std::isnan(y)); }

std::string show(float x) {
    char s[64];
    std::snprintf(s, sizeof s, "%a (0x%08x)", double(x), unsigned(std::bit_cast<u32>(x)));
    return s;
}

// Counts the checks that fail and keeps the first one's description (made only then) for the failure message.
struct tally {
    int bad = 0;
    std::string first;
    template <class Describe> void check(bool ok, Describe describe) {
        if (!ok && bad++ == 0) first = describe();
    }
    void check(bool ok, const char* what) {
        check(ok, [&] { return std::string(what); });
    }
};

// The inputs of lane k (counting on across trials): first all triples of special values, then random ones.
struct inputs {
    std::mt19937 rng{20240611};
    long k = 0;
    float random() {
        const u32 r = rng();
        if (r % 4 == 0) return std::bit_cast<float>(u32(rng()));  // any bit pattern: NaNs, denormals, ...
        if (r % 4 == 1) return specials[rng() % n_specials];
        const float m = std::uniform_real_distribution<float>(-2.0f, 2.0f)(rng);
        return std::ldexp(m, int(rng() % 80) - 40);
    }
    // Fills a, b, c (N lanes each).
    template <int N> void next(float* a, float* b, float* c) {
        for (int i = 0; i < N; ++i, ++k) {
            const long s = n_specials;
            if (k < s * s * s) {
                a[i] = specials[k % s], b[i] = specials[k / s % s], c[i] = specials[k / s / s % s];
            } else {
                a[i] = random(), b[i] = random(), c[i] = random();
            }
        }
    }
    long trials(int n) const { return (long(n_specials) * n_specials * n_specials + n - 1) / n + 3000; }
};

// The int and mask types that go with a vfloat type, and a name for messages.
template <class V> struct kin;
template <int N, bool B> struct kin<simd::vfloat<N, B>> {
    using vi = simd::vint<N, B>;
    using vm = simd::vmask<N, B>;
    static std::string name() { return (B ? "intrinsics, N = " : "fallback, N = ") + std::to_string(N); }
};

template <class V> std::array<float, V::size> lanes(V v) {
    std::array<float, V::size> r;
    v.storeu(r.data());
    return r;
}

// Calls f(std::type_identity<V>) for the vfloat types of both backends and N = 4, 8, 16. (Where a width has no
// intrinsics in this build, vfloat<N> is the fallback and is simply tested twice.)
template <class F> void for_each_backend(F f) {
    f(std::type_identity<simd::float4>());
    f(std::type_identity<simd::generic_vfloat<4>>());
    f(std::type_identity<simd::float8>());
    f(std::type_identity<simd::generic_vfloat<8>>());
    f(std::type_identity<simd::float16>());
    f(std::type_identity<simd::generic_vfloat<16>>());
}

// op(a, b, c) on vectors against sop(x, y, z) on each lane's floats; strict: every bit, NaN payloads too.
template <class V, class Op, class Sop> void check_float_op(const char* what, Op op, Sop sop, bool strict) {
    constexpr int N = V::size;
    inputs in;
    tally t;
    for (long trial = 0; trial < in.trials(N); ++trial) {
        alignas(64) float a[N], b[N], c[N];
        in.next<N>(a, b, c);
        const auto r = lanes(op(V::load(a), V::load(b), V::load(c)));
        for (int i = 0; i < N; ++i) {
            const float want = sop(a[i], b[i], c[i]);
            t.check(strict ? same_bits(r[i], want) : same_value(r[i], want), [&] {
                return std::string(what) + " lane " + std::to_string(i) + ": a = " + show(a[i]) + ", b = " +
                       show(b[i]) + ", c = " + show(c[i]) + ": got " + show(r[i]) + ", want " + show(want);
            });
        }
    }
    INFO(kin<V>::name() << ": " << what << ": " << t.bad << " lanes differ; first: " << t.first);
    CHECK(t.bad == 0);
}

// The same expression (a generic lambda) on vectors and on each lane's floats: the promise of the header.
template <class V, class Op> void check_same_as_scalar(const char* what, Op op, bool strict) {
    check_float_op<V>(what, op, op, strict);
}

// A comparison (or any mask-valued op) against the scalar bool, lane by lane; movemask must agree with [].
template <class V, class Op, class Sop> void check_mask_op(const char* what, Op op, Sop sop) {
    constexpr int N = V::size;
    inputs in;
    tally t;
    for (long trial = 0; trial < in.trials(N); ++trial) {
        alignas(64) float a[N], b[N], c[N];
        in.next<N>(a, b, c);
        const auto m = op(V::load(a), V::load(b), V::load(c));
        const unsigned bits = simd::movemask(m);
        for (int i = 0; i < N; ++i) {
            const bool want = sop(a[i], b[i], c[i]);
            t.check(m[i] == want && bool((bits >> i) & 1) == want, [&] {
                return std::string(what) + " lane " + std::to_string(i) + ": a = " + show(a[i]) + ", b = " +
                       show(b[i]) + ", c = " + show(c[i]) + ": want " + (want ? "true" : "false");
            });
        }
        t.check(bits >> N == 0, "movemask sets bits above lane N - 1");
    }
    INFO(kin<V>::name() << ": " << what << ": " << t.bad << " lanes differ; first: " << t.first);
    CHECK(t.bad == 0);
}

float scalar_min(float x, float y) { return x < y ? x : y; }
float scalar_max(float x, float y) { return x > y ? x : y; }

// The documented order of reduce_min/reduce_max: lane i against lane i + N/2, halving down to lane 0.
template <int N, class F> float halving_tree(std::array<float, N> x, F f) {
    for (int w = N / 2; w >= 1; w /= 2)
        for (int i = 0; i < w; ++i) x[i] = f(x[i], x[i + w]);
    return x[0];
}

// The slab test of one ray against a box: written once, for T = float (one box) and T = vfloat<N> (N boxes).
template <class T> struct slab_result {
    T tnear, tfar;
};
template <class T> slab_result<T> slab(const T (&org)[3], const T (&inv_dir)[3], const T (&lo)[3], const T (&hi)[3],
                                       T tmin, T tmax) {
    T tnear = tmin, tfar = tmax;
    for (int a = 0; a < 3; ++a) {
        const T t0 = (lo[a] - org[a]) * inv_dir[a];
        const T t1 = (hi[a] - org[a]) * inv_dir[a];
        tnear = simd::max(tnear, simd::min(t0, t1));
        tfar = simd::min(tfar, simd::max(t0, t1));
    }
    return {tnear, tfar};
}

}  // namespace
