// Exercise 09.2 chopped binning (6 points): entries and exits of references within one bin and across
// several; the clipper asked for each spanned bin's part, open-ended at the first and last; bins cleared
// first; empty parts growing nothing; and random references against a plain transcription of the rule.
#include "strahl/ch09/chopped_bins.hpp"
#include "clip_reference.hpp"
#include <catch2/catch.hpp>
#include <tuple>
#include <vector>

using namespace strahl;
using namespace strahl::ch09;

namespace {

struct clip_call {
    std::uint32_t tri;
    float lo, hi;
    bool operator==(const clip_call&) const = default;
};

bool same(const aabb& a, const aabb& b) { return a.min == b.min && a.max == b.max; }

}  // namespace

TEST_CASE("09.2 chopped bins: entries, exits and parts of references within one bin and across three", "[ch09][pts:2]") {
    // Four bins over x in [0, 4]: bin j covers [j, j + 1).
    const ch05::bin_mapping m = ch05::make_bin_mapping(0, 4, 4);
    const std::vector<triangle> tris = {{vec3(1.2f, 0, 0), vec3(1.8f, 0, 0), vec3(1.2f, 1, 0)},
                                        {vec3(0.5f, 0, 0), vec3(2.5f, 0, 0), vec3(0.5f, 2, 0)}};
    const std::vector<reference> refs = {{tris[0].bounds(), 0}, {tris[1].bounds(), 1}};
    std::vector<clip_call> calls;
    std::vector<chopped_bin> bins(4);
    chopped_binning(refs, 0, m, bins, [&](const reference& r, float lo, float hi) {
        calls.push_back({r.tri, lo, hi});
        return test::rounded_clip(tris[r.tri], 0, lo, hi, r.box);
    });
    // Triangle 0 lies in bin 1: no clipping. Triangle 1 spans bins 0, 1 and 2.
    CHECK(calls == std::vector<clip_call>{{1, -INFINITY, 1.0f}, {1, 1.0f, 2.0f}, {1, 2.0f, INFINITY}});
    CHECK((bins[0].entry == 1 && bins[0].exit == 0));
    CHECK((bins[1].entry == 1 && bins[1].exit == 1));
    CHECK((bins[2].entry == 0 && bins[2].exit == 1));
    CHECK((bins[3].entry == 0 && bins[3].exit == 0));
    // Triangle 1's parts: x in [0.5, 1] reaches y 2 (its corner); [1, 2] reaches y 1.5; [2, 2.5] reaches y 0.5.
    CHECK(same(bins[0].box, aabb{vec3(0.5f, 0, 0), vec3(1, 2, 0)}));
    CHECK(same(bins[1].box, aabb{vec3(1, 0, 0), vec3(2, 1.5f, 0)}));
    CHECK(same(bins[2].box, aabb{vec3(2, 0, 0), vec3(2.5f, 0.5f, 0)}));
    CHECK(bins[3].box.is_empty());
}

TEST_CASE("09.2 chopped bins: cleared first, and an empty part grows nothing", "[ch09][pts:1]") {
    const ch05::bin_mapping m = ch05::make_bin_mapping(0, 4, 4);
    std::vector<chopped_bin> bins(4);
    for (chopped_bin& b : bins) b.box = aabb{vec3(-9), vec3(9)}, b.entry = 7, b.exit = 5;
    const std::vector<reference> refs = {{aabb{vec3(0.5f, 0, 0), vec3(3.5f, 1, 0)}, 3}};
    chopped_binning(refs, 0, m, bins, [&](const reference& r, float lo, float hi) {
        if (lo == 1.0f) return aabb{};  // bin 1: nothing of it
        return aabb{vec3(std::max(lo, r.box.min.x), 0, 0), vec3(std::min(hi, r.box.max.x), 1, 0)};
    });
    CHECK((bins[0].entry == 1 && bins[0].exit == 0 && bins[3].entry == 0 && bins[3].exit == 1));
    CHECK((bins[1].entry == 0 && bins[1].exit == 0 && bins[2].entry == 0 && bins[2].exit == 0));
    CHECK(same(bins[0].box, aabb{vec3(0.5f, 0, 0), vec3(1, 1, 0)}));
    CHECK(bins[1].box.is_empty());
    CHECK(same(bins[2].box, aabb{vec3(2, 0, 0), vec3(3, 1, 0)}));
    CHECK(same(bins[3].box, aabb{vec3(3, 0, 0), vec3(3.5f, 1, 0)}));
}

TEST_CASE("09.2 chopped bins: the first and last bins by ch05::bin_index, clamped at the node's box", "[ch09][pts:1]") {
    // A reference reaching past the binned range (a node box rounded inwards) is clamped to bins 0 and k-1.
    const ch05::bin_mapping m = ch05::make_bin_mapping(0, 4, 4);
    std::vector<chopped_bin> bins(4);
    const std::vector<reference> refs = {{aabb{vec3(-1, 0, 0), vec3(5, 1, 1)}, 0}, {aabb{vec3(4, 0, 0), vec3(4, 1, 1)}, 1}};
    std::vector<clip_call> calls;
    chopped_binning(refs, 0, m, bins, [&](const reference& r, float lo, float hi) {
        calls.push_back({r.tri, lo, hi});
        return r.box;
    });
    CHECK(calls.size() == 4);  // reference 0 spans all four bins; reference 1 (at x = 4) lies in bin 3 alone
    CHECK((bins[0].entry == 1 && bins[3].exit == 2 && bins[3].entry == 1));
    CHECK(same(bins[3].box, aabb{vec3(-1, 0, 0), vec3(5, 1, 1)}));
}

TEST_CASE("09.2 chopped bins: random references, the rule transcribed plainly, on every axis", "[ch09][pts:2]") {
    pcg32 g(17);
    std::vector<triangle> tris;
    std::vector<reference> refs;
    for (std::uint32_t i = 0; i < 400; ++i) {
        const vec3 c(g.next_float() * 10, g.next_float() * 10, g.next_float() * 10);
        const float s = i % 4 == 0 ? 4.0f : 0.3f;
        const triangle t = test::random_triangle(g, -s, s);
        tris.push_back({t.v0 + c, t.v1 + c, t.v2 + c});
        aabb b = tris.back().bounds();
        if (i % 5 == 0) b.max.y = b.min.y + 0.5f * (b.max.y - b.min.y);  // a part of a triangle, split before
        refs.push_back({b, i});
    }
    for (int axis = 0; axis < 3; ++axis)
        for (const int k : {2, 7, 16}) {
            aabb all;
            for (const reference& r : refs) all.grow(r.box);
            const ch05::bin_mapping m = ch05::make_bin_mapping(all.min[axis], all.max[axis], k);
            const auto clip = [&](const reference& r, float lo, float hi) {
                return test::rounded_clip(tris[r.tri], axis, lo, hi, r.box);
            };
            std::vector<chopped_bin> got(static_cast<std::size_t>(k)), want(static_cast<std::size_t>(k));
            chopped_binning(refs, axis, m, got, clip);
            for (const reference& r : refs) {
                const int e = ch05::bin_index(m, r.box.min[axis]), x = ch05::bin_index(m, r.box.max[axis]);
                ++want[std::size_t(e)].entry, ++want[std::size_t(x)].exit;
                for (int j = e; j <= x; ++j)
                    want[std::size_t(j)].box.grow(e == x ? r.box : clip(r, j == e ? -INFINITY : bin_plane(m, j),
                                                                        j == x ? INFINITY : bin_plane(m, j + 1)));
            }
            std::size_t wrong = 0;
            for (int j = 0; j < k; ++j)
                wrong += got[std::size_t(j)].entry != want[std::size_t(j)].entry ||
                         got[std::size_t(j)].exit != want[std::size_t(j)].exit || !same(got[std::size_t(j)].box, want[std::size_t(j)].box);
            INFO("axis " << axis << ", " << k << " bins");
            CHECK(wrong == 0);
        }
}
