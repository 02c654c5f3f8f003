// Unit tests of the SIMD layer (strahl/simd.hpp), second part: masks, select, reductions, int lanes, casts,
// and the intrinsic and fallback backends against each other and scalar code on a slab test (the inputs and
// checks: simd_test_support.hpp; the first part: test_simd.cpp).
#include "simd_test_support.hpp"

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
