// Unit tests of the SIMD layer (strahl/simd.hpp): every operation, lane by lane and bit for bit, against the
// scalar C++ expression, for N = 4, 8, 16 and for both backends (intrinsics where this build enables them, and the
// fallback); then the two backends against each other on a slab test.
// Inputs: every combination of a list of special values (+-0, +-inf, NaNs, denormals, huge and tiny), then random
// numbers of all magnitudes and random bit patterns. NaN results may differ in payload (not promised); everything
// that only moves data (min, max, select, negation, loads, casts) must keep every bit.
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

TEST_CASE("simd: which widths use intrinsics, sizes and alignment", "[common][simd]") {
#if defined(__SSE2__)
    CHECK(simd::native<4>);
#endif
#if defined(__AVX__)
    CHECK(simd::native<8>);
#else
    CHECK_FALSE(simd::native<8>);
#endif
#if defined(__AVX512F__)
    CHECK(simd::native<16>);
#else
    CHECK_FALSE(simd::native<16>);
#endif
    CHECK(std::is_same_v<simd::float8, simd::generic_vfloat<8>> == !simd::native<8>);
    CHECK(sizeof(simd::float4) == 16);
    CHECK(sizeof(simd::float8) == 32);
    CHECK(sizeof(simd::float16) == 64);
    CHECK(sizeof(simd::int16) == 64);
    CHECK(alignof(simd::float4) == 16);
    CHECK(alignof(simd::float8) == 32);
    CHECK(alignof(simd::float16) == 64);
    CHECK(alignof(simd::generic_vfloat<16>) == 64);
    CHECK(alignof(simd::generic_vint<8>) == 32);
    CHECK(sizeof(simd::generic_vfloat<8>) == 32);
}

TEST_CASE("simd: broadcast, aligned and unaligned load and store, lane access and set keep every bit",
          "[common][simd]") {
    for_each_backend([]<class V>(std::type_identity<V>) {
        constexpr int N = V::size;
        using VI = typename kin<V>::vi;
        INFO(kin<V>::name());
        alignas(64) float buf[N + 1];
        alignas(64) i32 ibuf[N + 1];
        for (int i = 0; i <= N; ++i) buf[i] = specials[(i * 7) % n_specials], ibuf[i] = i32(0x9e3779b9u * u32(i));

        const V a = V::load(buf), u = V::loadu(buf + 1);
        alignas(64) float out[N + 1];
        a.store(out);
        for (int i = 0; i < N; ++i) CHECK(same_bits(out[i], buf[i]));
        for (int i = 0; i < N; ++i) CHECK(same_bits(a[i], buf[i]));
        u.storeu(out + 1);
        for (int i = 0; i < N; ++i) CHECK(same_bits(out[i + 1], buf[i + 1]));

        const V b(-0.0f);
        for (int i = 0; i < N; ++i) CHECK(same_bits(b[i], -0.0f));
        CHECK(same_bits(V()[N - 1], 0.0f));
        V s = a;
        s.set(N - 1, std::bit_cast<float>(0x7fc0abcdu));
        s.set(0, -inf);
        CHECK(same_bits(s[0], -inf));
        CHECK(std::bit_cast<u32>(s[N - 1]) == 0x7fc0abcdu);
        for (int i = 1; i < N - 1; ++i) CHECK(same_bits(s[i], buf[i]));

        const VI ia = VI::load(ibuf), iu = VI::loadu(ibuf + 1);
        alignas(64) i32 iout[N + 1];
        ia.store(iout);
        iu.storeu(iout + 1);
        for (int i = 0; i < N; ++i) CHECK(ia[i] == ibuf[i]);
        for (int i = 0; i < N; ++i) CHECK(iout[i + 1] == ibuf[i + 1]);
        VI is(-7);
        is.set(1, 42);
        CHECK(is[0] == -7);
        CHECK(is[1] == 42);
        CHECK(VI()[N - 1] == 0);
    });
}

TEST_CASE("simd: arithmetic (plus, minus, times, divide, negate, square root) rounds like scalar float, lane by lane",
          "[common][simd]") {
    for_each_backend([]<class V>(std::type_identity<V>) {
        check_same_as_scalar<V>("a + b", [](auto a, auto b, auto) { return a + b; }, false);
        check_same_as_scalar<V>("a - b", [](auto a, auto b, auto) { return a - b; }, false);
        check_same_as_scalar<V>("a * b", [](auto a, auto b, auto) { return a * b; }, false);
        check_same_as_scalar<V>("a / b", [](auto a, auto b, auto) { return a / b; }, false);
        check_same_as_scalar<V>("-a", [](auto a, auto, auto) { return -a; }, true);
        // A chain, in the same order as the scalar code: still the same bits.
        check_same_as_scalar<V>("(a - b) * c / (a + c)",
                                [](auto a, auto b, auto c) { return (a - b) * c / (a + c); }, false);
        check_float_op<V>("a + broadcast 0.1", [](V a, V, V) { return a + V(0.1f); },
                          [](float x, float, float) { return x + 0.1f; }, false);
        check_float_op<V>("sqrt(a)", [](V a, V, V) { return sqrt(a); },
                          [](float x, float, float) { return std::sqrt(x); }, false);
    });
}

TEST_CASE("simd: fmadd and fmsub round once, bit for bit like std::fma", "[common][simd]") {
    for_each_backend([]<class V>(std::type_identity<V>) {
        check_float_op<V>("fmadd(a, b, c)", [](V a, V b, V c) { return fmadd(a, b, c); },
                          [](float x, float y, float z) { return std::fma(x, y, z); }, false);
        check_same_as_scalar<V>("simd::fmadd(a, b, c)", [](auto a, auto b, auto c) { return simd::fmadd(a, b, c); },
                                false);
        check_float_op<V>("fmsub(a, b, c)", [](V a, V b, V c) { return fmsub(a, b, c); },
                          [](float x, float y, float z) { return std::fma(x, y, -z); }, false);
        // (1 + 2^-12)^2 = 1 + 2^-11 + 2^-24: rounding the product first loses the 2^-24, one rounding keeps it.
        const float a = 0x1.001p0f, c = 0x1.002p0f;
        INFO(kin<V>::name());
        CHECK(a * a - c == 0.0f);
        CHECK(fmsub(V(a), V(a), V(c))[V::size - 1] == 0x1p-24f);
        CHECK(fmadd(V(a), V(a), V(-c))[0] == 0x1p-24f);
    });
    CHECK(simd::fmadd(0x1.001p0f, 0x1.001p0f, -0x1.002p0f) == 0x1p-24f);  // the scalar (N = 1) overloads
    CHECK(simd::fmsub(0x1.001p0f, 0x1.001p0f, 0x1.002p0f) == 0x1p-24f);
}

TEST_CASE("simd: min and max follow x86 minps and maxps (NaN or a tie of zeros gives the second operand)",
          "[common][simd]") {
    for_each_backend([]<class V>(std::type_identity<V>) {
        check_float_op<V>("min(a, b)", [](V a, V b, V) { return min(a, b); },
                          [](float x, float y, float) { return scalar_min(x, y); }, true);
        check_float_op<V>("max(a, b)", [](V a, V b, V) { return max(a, b); },
                          [](float x, float y, float) { return scalar_max(x, y); }, true);
        check_same_as_scalar<V>("simd::min(simd::max(a, b), c)",
                                [](auto a, auto b, auto c) { return simd::min(simd::max(a, b), c); }, true);
        INFO(kin<V>::name());
        CHECK(min(V(qnan), V(1.0f))[0] == 1.0f);  // the second operand where either is NaN
        CHECK(std::isnan(min(V(1.0f), V(qnan))[0]));
        CHECK(max(V(qnan), V(1.0f))[0] == 1.0f);
        CHECK(std::isnan(max(V(1.0f), V(qnan))[0]));
        CHECK(same_bits(min(V(-0.0f), V(0.0f))[0], 0.0f));  // a tie of zeros: the second operand
        CHECK(same_bits(min(V(0.0f), V(-0.0f))[0], -0.0f));
        CHECK(same_bits(max(V(-0.0f), V(0.0f))[0], 0.0f));
        CHECK(same_bits(max(V(0.0f), V(-0.0f))[0], -0.0f));
    });
    CHECK(simd::min(qnan, 1.0f) == 1.0f);  // N = 1 follows the same rule
    CHECK(same_bits(simd::max(0.0f, -0.0f), -0.0f));
}

TEST_CASE("simd: comparisons follow IEEE (NaN compares false, except for !=)", "[common][simd]") {
    for_each_backend([]<class V>(std::type_identity<V>) {
        using F = float;
        check_mask_op<V>("a < b", [](V a, V b, V) { return a < b; }, [](F x, F y, F) { return x < y; });
        check_mask_op<V>("a <= b", [](V a, V b, V) { return a <= b; }, [](F x, F y, F) { return x <= y; });
        check_mask_op<V>("a > b", [](V a, V b, V) { return a > b; }, [](F x, F y, F) { return x > y; });
        check_mask_op<V>("a >= b", [](V a, V b, V) { return a >= b; }, [](F x, F y, F) { return x >= y; });
        check_mask_op<V>("a == b", [](V a, V b, V) { return a == b; }, [](F x, F y, F) { return x == y; });
        check_mask_op<V>("a != b", [](V a, V b, V) { return a != b; }, [](F x, F y, F) { return x != y; });
        INFO(kin<V>::name());
        CHECK(all(V(qnan) != V(qnan)));
        CHECK(none(V(qnan) == V(qnan)));
        CHECK(all(V(-0.0f) == V(0.0f)));
    });
}

TEST_CASE("simd: masks: and, or, xor, not, andnot, movemask and its inverse from_bits, any, all, none, popcount", "[common][simd]") {
    for_each_backend([]<class V>(std::type_identity<V>) {
        using M = typename kin<V>::vm;
        constexpr int N = V::size;
        // Two masks from comparisons (a < b, b < c), then each mask op against the bools.
        const auto lt_ab = [](float x, float y, float) { return x < y; };
        const auto lt_bc = [](float, float y, float z) { return y < z; };
        check_mask_op<V>("m & n", [](V a, V b, V c) { return (a < b) & (b < c); },
                         [&](float x, float y, float z) { return lt_ab(x, y, z) && lt_bc(x, y, z); });
        check_mask_op<V>("m | n", [](V a, V b, V c) { return (a < b) | (b < c); },
                         [&](float x, float y, float z) { return lt_ab(x, y, z) || lt_bc(x, y, z); });
        check_mask_op<V>("m ^ n", [](V a, V b, V c) { return (a < b) ^ (b < c); },
                         [&](float x, float y, float z) { return lt_ab(x, y, z) != lt_bc(x, y, z); });
        check_mask_op<V>("~m", [](V a, V b, V) { return ~(a < b); }, [](float x, float y, float) {
            return !(x < y);
        });
        check_mask_op<V>("andnot(m, n)", [](V a, V b, V c) { return andnot(a < b, b < c); },
                         [&](float x, float y, float z) { return lt_ab(x, y, z) && !lt_bc(x, y, z); });

        // any, all, none, popcount and movemask on every single-lane mask, on all and none, and on random masks.
        INFO(kin<V>::name());
        CHECK(movemask(M(true)) == (N == 32 ? ~0u : (1u << N) - 1));
        CHECK(movemask(M(false)) == 0u);
        CHECK(movemask(M()) == 0u);
        CHECK(all(M(true)));
        CHECK(any(M(true)));
        CHECK_FALSE(none(M(true)));
        CHECK(none(M(false)));
        CHECK_FALSE(any(M(false)));
        CHECK_FALSE(all(M(false)));
        CHECK(popcount(M(true)) == N);
        CHECK(popcount(M(false)) == 0);
        alignas(64) float x[N];
        for (int lane = 0; lane < N; ++lane) {
            for (int i = 0; i < N; ++i) x[i] = i == lane ? 1.0f : 0.0f;
            const M one = V::load(x) > V(0.5f);
            CHECK(movemask(one) == 1u << lane);
            CHECK(any(one));
            CHECK_FALSE(none(one));
            CHECK(all(one) == (N == 1));
            CHECK(popcount(one) == 1);
            CHECK(one[lane]);
            CHECK_FALSE(all(~one));
            CHECK(popcount(~one) == N - 1);
        }
        std::mt19937 rng(7);
        for (int trial = 0; trial < 200; ++trial) {
            unsigned want = 0;
            for (int i = 0; i < N; ++i) {
                x[i] = float(rng() % 2);
                want |= unsigned(x[i] != 0.0f) << i;
            }
            const M m = V::load(x) != V(0.0f);
            CHECK(movemask(m) == want);
            // from_bits, movemask's inverse (the bits above lane N - 1 ignored).
            M back;
            if constexpr (std::is_same_v<M, simd::vmask<N>>) back = simd::from_bits<N>(want | ~simd::detail::lane_bits(N));
            else back = simd::from_bits_generic<N>(want | ~simd::detail::lane_bits(N));
            CHECK(movemask(back) == want);
            CHECK(movemask(back & m) == want);
            CHECK(popcount(m) == std::popcount(want));
            CHECK(any(m) == (want != 0));
            CHECK(none(m) == (want == 0));
            CHECK(all(m) == (want == (1u << N) - 1));
        }
    });
    CHECK(simd::any(true));
    CHECK(simd::none(false));
    CHECK_FALSE(simd::all(false));
}

TEST_CASE("simd: select takes a where the mask is set and b elsewhere, bit for bit", "[common][simd]") {
    for_each_backend([]<class V>(std::type_identity<V>) {
        using VI = typename kin<V>::vi;
        check_float_op<V>("select(a < c, a, b)", [](V a, V b, V c) { return select(a < c, a, b); },
                          [](float x, float y, float z) { return x < z ? x : y; }, true);
        check_same_as_scalar<V>("simd::select(a >= b, c, a)",
                                [](auto a, auto b, auto c) { return simd::select(a >= b, c, a); }, true);
        check_float_op<V>("select(a != a, b, c)", [](V a, V b, V c) { return select(a != a, b, c); },
                          [](float x, float y, float z) { return x != x ? y : z; }, true);
        // On int lanes (NaN bit patterns as ints must survive too).
        check_float_op<V>("select on ints",
                          [](V a, V b, V c) { return as_float(select(b <= c, as_int(a), as_int(c))); },
                          [](float x, float y, float z) { return y <= z ? x : z; }, true);
        INFO(kin<V>::name());
        CHECK(select(typename kin<V>::vm(true), VI(3), VI(-4))[0] == 3);
        CHECK(select(typename kin<V>::vm(false), VI(3), VI(-4))[V::size - 1] == -4);
    });
    CHECK(simd::select(false, 1.0f, 2.0f) == 2.0f);
    CHECK(simd::select(true, i32(1), i32(2)) == 1);
}

TEST_CASE("simd: reduce_min and reduce_max follow the documented halving tree, NaN and zeros included",
          "[common][simd]") {
    for_each_backend([]<class V>(std::type_identity<V>) {
        constexpr int N = V::size;
        inputs in;
        tally t;
        for (long trial = 0; trial < in.trials(N); ++trial) {
            alignas(64) std::array<float, N> a, b, c;
            in.next<N>(a.data(), b.data(), c.data());
            const V v = V::load(a.data());
            const float lo = reduce_min(v), hi = reduce_max(v);
            const float want_lo = halving_tree<N>(a, scalar_min), want_hi = halving_tree<N>(a, scalar_max);
            t.check(same_bits(lo, want_lo), [&] { return "reduce_min: " + show(lo) + ", want " + show(want_lo); });
            t.check(same_bits(hi, want_hi), [&] { return "reduce_max: " + show(hi) + ", want " + show(want_hi); });
        }
        INFO(kin<V>::name() << ": " << t.bad << " results differ; first: " << t.first);
        CHECK(t.bad == 0);
        // Without NaN and zeros the order does not matter: the smallest and the largest lane.
        alignas(64) float x[N];
        for (int lane = 0; lane < N; ++lane) {
            for (int i = 0; i < N; ++i) x[i] = float(i + 1);
            x[lane] = -5.0f;
            CHECK(reduce_min(V::load(x)) == -5.0f);
            x[lane] = 1000.0f;
            CHECK(reduce_max(V::load(x)) == 1000.0f);
        }
    });
}

TEST_CASE("simd: int lanes: plus and minus wrap around, signed comparisons, broadcast", "[common][simd]") {
    for_each_backend([]<class V>(std::type_identity<V>) {
        using VI = typename kin<V>::vi;
        constexpr int N = VI::size;
        constexpr i32 big = std::numeric_limits<i32>::max(), small = std::numeric_limits<i32>::min();
        const i32 edge[] = {0, 1, -1, 2, -2, 1000, -1000, big, small, big - 1, small + 1};
        constexpr int n_edge = int(std::size(edge));
        std::mt19937 rng(99);
        tally t;
        for (int trial = 0; trial < 3000; ++trial) {
            alignas(64) i32 a[N], b[N];
            for (int i = 0; i < N; ++i) {
                const int k = trial * N + i;
                a[i] = k < n_edge * n_edge ? edge[k % n_edge] : i32(rng());
                b[i] = k < n_edge * n_edge ? edge[k / n_edge] : (rng() % 4 == 0 ? a[i] : i32(rng()));
            }
            const VI x = VI::load(a), y = VI::load(b);
            const VI sum = x + y, diff = x - y;
            const unsigned lt = movemask(x < y), le = movemask(x <= y), gt = movemask(x > y), ge = movemask(x >= y),
                           eq = movemask(x == y), ne = movemask(x != y);
            for (int i = 0; i < N; ++i) {
                const auto at = [&](const char* op) {
                    return [=, &a, &b] {
                        return op + (" lane " + std::to_string(i) + ": " + std::to_string(a[i]) + ", " +
                                     std::to_string(b[i]));
                    };
                };
                t.check(sum[i] == i32(u32(a[i]) + u32(b[i])), at("+"));
                t.check(diff[i] == i32(u32(a[i]) - u32(b[i])), at("-"));
                t.check(bool((lt >> i) & 1) == (a[i] < b[i]), at("<"));
                t.check(bool((le >> i) & 1) == (a[i] <= b[i]), at("<="));
                t.check(bool((gt >> i) & 1) == (a[i] > b[i]), at(">"));
                t.check(bool((ge >> i) & 1) == (a[i] >= b[i]), at(">="));
                t.check(bool((eq >> i) & 1) == (a[i] == b[i]), at("=="));
                t.check(bool((ne >> i) & 1) == (a[i] != b[i]), at("!="));
            }
        }
        INFO(kin<V>::name() << ": " << t.bad << " lanes differ; first: " << t.first);
        CHECK(t.bad == 0);
        CHECK(VI(-3)[N - 1] == -3);
    });
}

TEST_CASE("simd: as_int and as_float reinterpret bits, to_float rounds, to_int truncates", "[common][simd]") {
    for_each_backend([]<class V>(std::type_identity<V>) {
        using VI = typename kin<V>::vi;
        constexpr int N = V::size;
        check_float_op<V>("as_float(as_int(a))", [](V a, V, V) { return as_float(as_int(a)); },
                          [](float x, float, float) { return x; }, true);
        check_float_op<V>("to_float(as_int(a))", [](V a, V, V) { return to_float(as_int(a)); },
                          [](float x, float, float) { return float(std::bit_cast<i32>(x)); }, true);
        // to_int: truncation; INT32_MIN where the scalar cast is undefined (NaN, out of range), as cvttps2dq does.
        check_float_op<V>("to_int(a)", [](V a, V, V) { return as_float(to_int(a)); },
                          [](float x, float, float) {
                              const bool in_range = x >= -2147483648.0f && x < 2147483648.0f;
                              return std::bit_cast<float>(in_range ? i32(x) : std::numeric_limits<i32>::min());
                          }, true);
        INFO(kin<V>::name());
        CHECK(as_int(V(-0.0f))[0] == std::numeric_limits<i32>::min());
        CHECK(as_int(V(1.0f))[N - 1] == 0x3f800000);
        CHECK(to_int(V(-2.99f))[0] == -2);
        CHECK(to_float(VI(16777217))[0] == 16777216.0f);  // rounds to nearest even
    });
}

TEST_CASE("simd: the intrinsic and fallback backends agree bit for bit, and with scalar code, on a slab test",
          "[common][simd]") {
    // One ray against N boxes: with vfloat<N> (intrinsics where enabled), with generic_vfloat<N>, and box by box
    // with the same template on plain floats. Boxes and rays include empty boxes, zero directions (inv = inf),
    // NaN and rays starting on a face.
    const auto run = []<int N>(std::integral_constant<int, N>) {
        using NV = simd::vfloat<N>;
        using GV = simd::generic_vfloat<N>;
        inputs in;
        tally t;
        for (long trial = 0; trial < 4000; ++trial) {
            alignas(64) float lo[3][N], hi[3][N], dummy[N];
            for (int a = 0; a < 3; ++a) in.next<N>(lo[a], hi[a], dummy);
            float org[3], inv[3];
            for (int a = 0; a < 3; ++a) {
                org[a] = in.random();
                inv[a] = trial % 3 == 0 ? 1.0f / specials[in.rng() % n_specials] : 1.0f / in.random();
            }
            const float tmax = trial % 2 ? inf : in.random();
            const auto wide = [&]<class V>(std::type_identity<V>) {
                const V o[3] = {V(org[0]), V(org[1]), V(org[2])}, d[3] = {V(inv[0]), V(inv[1]), V(inv[2])};
                const V l[3] = {V::load(lo[0]), V::load(lo[1]), V::load(lo[2])};
                const V h[3] = {V::load(hi[0]), V::load(hi[1]), V::load(hi[2])};
                return slab<V>(o, d, l, h, V(0.0f), V(tmax));
            };
            const auto n = wide(std::type_identity<NV>()), g = wide(std::type_identity<GV>());
            const unsigned n_hit = movemask(n.tnear <= n.tfar), g_hit = movemask(g.tnear <= g.tfar);
            t.check(n_hit == g_hit, "hit masks differ");
            t.check(same_bits(reduce_min(select(n.tnear <= n.tfar, n.tnear, NV(inf))),
                              reduce_min(select(g.tnear <= g.tfar, g.tnear, GV(inf)))), "nearest entry differs");
            for (int i = 0; i < N; ++i) {
                const float l[3] = {lo[0][i], lo[1][i], lo[2][i]}, h[3] = {hi[0][i], hi[1][i], hi[2][i]};
                const auto s = slab<float>(org, inv, l, h, 0.0f, tmax);
                const auto at = [&](const char* what) { return [=] { return "box " + std::to_string(i) + what; }; };
                t.check(same_value(n.tnear[i], g.tnear[i]) && same_value(n.tfar[i], g.tfar[i]), at(": backends"));
                t.check(same_value(n.tnear[i], s.tnear) && same_value(n.tfar[i], s.tfar), at(": scalar"));
                t.check(bool((n_hit >> i) & 1) == (s.tnear <= s.tfar), at(": scalar hit"));
            }
            // And a few more operations, the two backends on the same inputs.
            const NV na = NV::load(lo[0]), nb = NV::load(hi[0]), nc = NV::load(lo[1]);
            const GV ga = GV::load(lo[0]), gb = GV::load(hi[0]), gc = GV::load(lo[1]);
            const auto r1 = lanes(fmadd(na, nb, nc) / (na - nc)), r2 = lanes(fmadd(ga, gb, gc) / (ga - gc));
            const auto r3 = lanes(select(na >= nb, min(na, nc), -max(nb, nc)));
            const auto r4 = lanes(select(ga >= gb, min(ga, gc), -max(gb, gc)));
            for (int i = 0; i < N; ++i) {
                t.check(same_value(r1[i], r2[i]), "fmadd / difference: backends");
                t.check(same_bits(r3[i], r4[i]), "select, min, max: backends");
                t.check(to_int(na)[i] == to_int(ga)[i] && as_int(nb)[i] == as_int(gb)[i], "to_int, as_int");
            }
            t.check(movemask(na != nb) == movemask(ga != gb) && popcount(na < nc) == popcount(ga < gc),
                    "masks: backends");
        }
        INFO("N = " << N << (simd::native<N> ? " (intrinsics against fallback)" : " (fallback only)") << ": "
                    << t.bad << " checks failed; first: " << t.first);
        CHECK(t.bad == 0);
    };
    run(std::integral_constant<int, 4>());
    run(std::integral_constant<int, 8>());
    run(std::integral_constant<int, 16>());
}
