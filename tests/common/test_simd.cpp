// Unit tests of the SIMD layer (strahl/simd.hpp): every operation, lane by lane and bit for bit, against the
// scalar C++ expression, for N = 4, 8, 16 and for both backends (intrinsics where this build enables them, and the
// fallback); then the two backends against each other on a slab test.
// Inputs: every combination of a list of special values (+-0, +-inf, NaNs, denormals, huge and tiny), then random
// numbers of all magnitudes and random bit patterns. NaN results may differ in payload (not promised); everything
// that only moves data (min, max, select, negation, loads, casts) must keep every bit.
// This file: the widths, loads and stores, arithmetic, fmadd, min and max, comparisons (masks, select,
// reductions, int lanes, casts and the two backends against each other: test_simd_masks.cpp).
#include "simd_test_support.hpp"

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
