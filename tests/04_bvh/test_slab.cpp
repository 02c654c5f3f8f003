// Exercise 04.1 the robust slab test (10 points). Only slab_test, on hand-made boxes and rays, and on rays
// aimed at boxes' edges and corners against a slab test in long double.
#include "strahl/ch04/traverse.hpp"
#include "slab_cases.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <iomanip>
#include <sstream>

using namespace strahl;
using namespace strahl::ch04;

namespace {
const aabb unit{vec3(0.0f), vec3(1.0f)};
bool meets(const aabb& b, vec3 org, vec3 dir, float tmin = 0.0f, float tmax = inf) {
    return slab_test(b, org, 1.0f / dir, tmin, tmax);
}
}  // namespace

TEST_CASE("04.1 slab test: rays that meet the box and rays that miss it", "[ch04][pts:3]") {
    CHECK(meets(unit, vec3(-1, 0.5f, 0.5f), vec3(1, 0, 0)));
    CHECK(meets(unit, vec3(2, 0.5f, 0.5f), vec3(-1, 0, 0)));
    CHECK(meets(unit, vec3(-1, -1, -1), vec3(1, 1, 1)));            // through the corners
    CHECK(meets(unit, vec3(0.5f), vec3(0.3f, -0.2f, 0.7f)));         // from inside
    CHECK_FALSE(meets(unit, vec3(-1, 0.5f, 0.5f), vec3(-1, 0, 0)));  // box behind the ray
    CHECK_FALSE(meets(unit, vec3(-1, 2.5f, 0.5f), vec3(1, 1, 0)));   // passes beside it
    CHECK_FALSE(meets(unit, vec3(-1, -1, 0.5f), vec3(1, 3, 0)));     // slabs' intervals do not overlap
    // The interval [tmin, tmax] clips: the box lies at t in [1, 2].
    CHECK(meets(unit, vec3(-1, 0.5f, 0.5f), vec3(1, 0, 0), 0.0f, 1.5f));
    CHECK(meets(unit, vec3(-1, 0.5f, 0.5f), vec3(1, 0, 0), 1.5f, 5.0f));
    CHECK_FALSE(meets(unit, vec3(-1, 0.5f, 0.5f), vec3(1, 0, 0), 0.0f, 0.9f));
    CHECK_FALSE(meets(unit, vec3(-1, 0.5f, 0.5f), vec3(1, 0, 0), 2.1f, 5.0f));
}

TEST_CASE("04.1 slab test: closed boxes, touching counts, flat boxes are hit", "[ch04][pts:2]") {
    CHECK(meets(unit, vec3(-1, 1, 0.5f), vec3(1, 0, 0)));                  // grazing the face y = 1
    CHECK(meets(unit, vec3(-1, 0.5f, 0.5f), vec3(1, 0, 0), 0.0f, 1.0f));   // tmax exactly at the entry
    const aabb flat{vec3(0, 0, 0.5f), vec3(1, 1, 0.5f)};                   // zero thickness on z
    CHECK(meets(flat, vec3(0.5f, 0.5f, 2), vec3(0, 0, -1)));
    CHECK(meets(flat, vec3(0.25f, 0.5f, -3), vec3(0.1f, 0.05f, 1)));
    CHECK_FALSE(meets(flat, vec3(0.5f, 0.5f, 2), vec3(0, 0, 1)));
    // A box one ulp wide, met along the diagonal.
    const aabb tiny{vec3(1.0f), vec3(1.0000001f)};
    CHECK(meets(tiny, vec3(0.0f), vec3(1.0f)));
}

TEST_CASE("04.1 slab test: direction components of +0 and -0, origins on a slab plane", "[ch04][pts:3]") {
    for (const float z : {0.0f, -0.0f}) {
        INFO("the zero direction components are " << (std::signbit(z) ? "-0" : "+0"));
        // Parallel to x's slab, inside it, outside it, and exactly on its planes (0 * inf = NaN there).
        CHECK(meets(unit, vec3(0.5f, -1, 0.5f), vec3(z, 1, z)));
        CHECK_FALSE(meets(unit, vec3(1.5f, -1, 0.5f), vec3(z, 1, z)));
        CHECK_FALSE(meets(unit, vec3(-0.5f, -1, 0.5f), vec3(z, 1, z)));
        CHECK(meets(unit, vec3(0.0f, -1, 0.5f), vec3(z, 1, z)));
        CHECK(meets(unit, vec3(1.0f, -1, 0.5f), vec3(z, 1, z)));
        CHECK(meets(unit, vec3(0.0f, -1, 0.0f), vec3(z, 1, z)));  // along an edge
        CHECK_FALSE(meets(unit, vec3(0.0f, -1, 0.0f), vec3(z, -1, z)));  // the same edge, going away
        // In the plane of a flat box.
        const aabb flat{vec3(0, 0, 0.5f), vec3(1, 1, 0.5f)};
        CHECK(meets(flat, vec3(-1, 0.5f, 0.5f), vec3(1, z, z)));
        CHECK_FALSE(meets(flat, vec3(-1, 0.5f, 0.6f), vec3(1, z, z)));
    }
    // Starting on a face, going in and going out.
    CHECK(meets(unit, vec3(0, 0.5f, 0.5f), vec3(1, 0.1f, 0)));
    CHECK(meets(unit, vec3(0, 0.5f, 0.5f), vec3(-1, 0.1f, 0)));  // touches at t = 0
    CHECK_FALSE(meets(unit, vec3(0, 0.5f, 0.5f), vec3(-1, 0.1f, 0), 1e-3f, inf));
}

TEST_CASE("04.1 slab test: conservative, no box the exact ray meets is missed at its edges and corners",
          "[ch04][pts:2]") {
    // Rays aimed at (and one or two floats beside) the edges and corners of boxes 1e-3 to 1e3 wide, placed
    // up to 1e7 from the origin. Where the slab test in long double says the ray meets the box, slab_test
    // must too: rounding the far plane's t below the near one's would lose the box, and with it every
    // triangle inside. That is what the exit's widening by 1 + 2 gamma(3) is for.
    int tested = 0, missed = 0;
    std::ostringstream first_missed;  // the first box missed, with every digit of its floats
    first_missed << std::setprecision(9);
    for (const float offset : {0.0f, 1.0f, 1e3f, 1e5f, 1e7f})
        for (const float size : {1e-3f, 1.0f, 1e3f})
            for (const test::grazing_case& k : test::grazing_cases(offset, size, 41, 2000)) {
                if (!test::exact_entry(k.box, k.r, -1e30L, 1e30L)) continue;
                ++tested;
                if (!slab_test(k.box, k.r.org, 1.0f / k.r.dir, -1e30f, 1e30f) && missed++ == 0)
                    first_missed << "(of boxes " << size << " wide at " << offset << " from the origin): box ("
                                 << k.box.min.x << ", " << k.box.min.y << ", " << k.box.min.z << ") - ("
                                 << k.box.max.x << ", " << k.box.max.y << ", " << k.box.max.z << "), ray from ("
                                 << k.r.org.x << ", " << k.r.org.y << ", " << k.r.org.z << ") along ("
                                 << k.r.dir.x << ", " << k.r.dir.y << ", " << k.r.dir.z << ")";
            }
    CHECK(tested > 10000);
    INFO(missed << " of " << tested << " boxes the exact ray meets were missed; the first " << first_missed.str());
    CHECK(missed == 0);
}
