// Exercise 05.3 prefix and suffix sweeps (10 points). Only best_boundary, against every boundary evaluated
// on its own.
#include "strahl/ch05/sah.hpp"
#include "strahl/rng.hpp"
#include <catch2/catch.hpp>
#include <sstream>
#include <string>
#include <vector>

using namespace strahl;
using namespace strahl::ch05;

namespace {

aabb box(vec3 lo, vec3 hi) { return {lo, hi}; }

// Every boundary on its own: the unions of bins [0, b) and [b, k), the formula written out.
bin_split one_by_one(const std::vector<bin>& bins, const sah_costs& c, float area) {
    bin_split best;
    for (std::size_t b = 1; b < bins.size(); ++b) {
        aabb l, r;
        std::uint64_t nl = 0, nr = 0;
        for (std::size_t i = 0; i < b; ++i) l.grow(bins[i].box), nl += bins[i].count;
        for (std::size_t i = b; i < bins.size(); ++i) r.grow(bins[i].box), nr += bins[i].count;
        if (nl == 0 || nr == 0) continue;
        const float cost = c.traversal + c.intersection * (l.surface_area() * float(nl) + r.surface_area() * float(nr)) / area;
        if (cost < best.cost) best = {int(b), cost};
    }
    return best;
}

// The bins' counts, for a failure message (only for a few bins; an empty bin counts 0).
std::string counts_of(const std::vector<bin>& bins) {
    if (bins.size() > 8) return std::to_string(bins.size()) + " bins (too many to list)";
    std::ostringstream out;
    out << "bin counts [";
    for (std::size_t i = 0; i < bins.size(); ++i) out << (i ? ", " : "") << bins[i].count;
    out << "]";
    return out.str();
}

}  // namespace

TEST_CASE("05.3 sweeps: two bins far apart split between them", "[ch05][pts:3]") {
    std::vector<bin> bins(4);
    bins[0] = {box(vec3(0), vec3(1)), 3};
    bins[3] = {box(vec3(9, 0, 0), vec3(10, 1, 1)), 2};
    std::vector<float> scratch(4);
    const float area = box(vec3(0), vec3(10, 1, 1)).surface_area();  // 42
    const bin_split s = best_boundary(bins, scratch, {1.0f, 1.0f}, area);
    // Boundaries 1, 2 and 3 all separate the two clusters at the same cost; the lowest index wins.
    CHECK(s.index == 1);
    CHECK(s.cost == Approx(1.0f + (6.0f * 3.0f + 6.0f * 2.0f) / 42.0f));
}

TEST_CASE("05.3 sweeps: no boundary with an empty side, fewer than two bins", "[ch05][pts:2]") {
    std::vector<float> scratch(8);
    std::vector<bin> one_full(5);
    one_full[2] = {box(vec3(0), vec3(1)), 7};
    const bin_split s = best_boundary(one_full, scratch, {}, 6.0f);
    CHECK(s.index == 0);
    CHECK(s.cost == std::numeric_limits<float>::infinity());
    const std::vector<bin> single = {{box(vec3(0), vec3(1)), 3}};
    CHECK(best_boundary(single, scratch, {}, 6.0f).index == 0);
    CHECK(best_boundary(std::span<const bin>(), scratch, {}, 6.0f).index == 0);
}

TEST_CASE("05.3 sweeps: random bins, the same boundary and cost as every boundary on its own", "[ch05][pts:5]") {
    pcg32 g(5);
    int checked = 0;
    for (const int k : {2, 3, 8, 16, 33, 256}) {
        for (int trial = 0; trial < 20; ++trial) {
            std::vector<bin> bins(std::size_t(k), bin{});
            aabb all;
            for (bin& b : bins) {
                if (g.next_float() < 0.3f) continue;  // some bins stay empty
                const vec3 lo(g.next_float() * 10.0f, g.next_float(), g.next_float());
                b = {box(lo, lo + vec3(g.next_float(), g.next_float(), g.next_float()) + 0.01f), 1 + g.next_u32() % 50};
                all.grow(b.box);
            }
            if (all.is_empty()) continue;
            const sah_costs c{0.5f + g.next_float(), 0.5f + g.next_float()};
            std::vector<float> scratch(std::size_t(k), -1.0f);
            const bin_split s = best_boundary(bins, scratch, c, all.surface_area());
            const bin_split ref = one_by_one(bins, c, all.surface_area());
            INFO("k = " << k << " bins, trial " << trial << ": " << counts_of(bins) << ", C_T " << c.traversal
                        << ", C_I " << c.intersection << ", parent area " << all.surface_area());
            CHECK(s.index == ref.index);
            CHECK(s.cost == Approx(ref.cost).epsilon(1e-5));
            ++checked;
        }
    }
    CHECK(checked > 100);
}
