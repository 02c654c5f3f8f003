// Exercise 09.1 clip a triangle to a slab (6 points): hand-computed parts (a right triangle and a tilted
// one, slabs inside, across, beside and open-ended), the intersection with the reference's box, corners
// on the planes and degenerate triangles, and random triangles and slabs against a plain clipper in long
// double: the box holds the exact part and is no larger than rounding allows; and crossing points that
// float rounds to nearest on the wrong side (0.1, 0.7), and the random cases again with no tolerance: the box
// rounded outwards holds the exact part.
#include "strahl/ch09/clip.hpp"
#include "clip_reference.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch09;

namespace {

const aabb everything{vec3(-INFINITY), vec3(INFINITY)};

void check_box(const aabb& got, vec3 lo, vec3 hi) {
    INFO("got [" << got.min.x << " " << got.min.y << " " << got.min.z << "] - [" << got.max.x << " " << got.max.y
                 << " " << got.max.z << "]");
    CHECK(got.min == lo);
    CHECK(got.max == hi);
}

}  // namespace

TEST_CASE("09.1 clip: a right triangle and a tilted one, by hand", "[ch09][pts:2]") {
    const triangle right{vec3(0, 0, 0), vec3(2, 0, 0), vec3(0, 2, 0)};
    check_box(clip_to_slab(right, 0, 1, 2, everything), vec3(1, 0, 0), vec3(2, 1, 0));  // the tip
    check_box(clip_to_slab(right, 0, 0, 1, everything), vec3(0, 0, 0), vec3(1, 2, 0));  // the wide part
    check_box(clip_to_slab(right, 1, -INFINITY, 1, everything), vec3(0, 0, 0), vec3(2, 1, 0));
    check_box(clip_to_slab(right, 0, -INFINITY, INFINITY, everything), vec3(0, 0, 0), vec3(2, 2, 0));
    check_box(clip_to_slab(right, 0, 0.5f, 1.5f, everything), vec3(0.5f, 0, 0), vec3(1.5f, 1.5f, 0));
    CHECK(clip_to_slab(right, 0, 3, 4, everything).is_empty());     // beside it
    CHECK(clip_to_slab(right, 2, 0.5f, 1, everything).is_empty());  // above its plane
    // Corners (0,0,0), (4,0,4), (0,4,0): x = 1 crosses the edges at (1,0,1) and (1,3,1), x = 3 at (3,0,3)
    // and (3,1,3).
    const triangle tilted{vec3(0, 0, 0), vec3(4, 0, 4), vec3(0, 4, 0)};
    check_box(clip_to_slab(tilted, 0, 1, 3, everything), vec3(1, 0, 1), vec3(3, 3, 3));
    check_box(clip_to_slab(tilted, 2, 1, 3, everything), vec3(1, 0, 1), vec3(3, 3, 3));
    check_box(clip_to_slab(tilted, 1, 1, 2, everything), vec3(0, 1, 0), vec3(3, 2, 3));
}

TEST_CASE("09.1 clip: intersected with the reference's box, empty where they do not meet", "[ch09][pts:1]") {
    const triangle tilted{vec3(0, 0, 0), vec3(4, 0, 4), vec3(0, 4, 0)};
    check_box(clip_to_slab(tilted, 0, 1, 3, aabb{vec3(0, 0, 0), vec3(4, 2, 4)}), vec3(1, 0, 1), vec3(3, 2, 3));
    check_box(clip_to_slab(tilted, 0, -INFINITY, INFINITY, aabb{vec3(1, 1, 1), vec3(2, 2, 2)}), vec3(1, 1, 1), vec3(2, 2, 2));
    CHECK(clip_to_slab(tilted, 0, 1, 3, aabb{vec3(5, 0, 0), vec3(6, 4, 4)}).is_empty());
    CHECK(clip_to_slab(tilted, 0, 1, 3, aabb{}).is_empty());
    // The slab and the box each meet the triangle, but not in the same place.
    CHECK(clip_to_slab(tilted, 0, 3, 4, aabb{vec3(0, 0, 0), vec3(4, 4, 2)}).is_empty());
}

TEST_CASE("09.1 clip: corners on a plane are inside, a triangle in the plane, lines and points", "[ch09][pts:1]") {
    const triangle in_plane{vec3(1, 0, 0), vec3(1, 2, 0), vec3(1, 0, 2)};  // x = 1 everywhere
    check_box(clip_to_slab(in_plane, 0, 1, 2, everything), vec3(1, 0, 0), vec3(1, 2, 2));
    check_box(clip_to_slab(in_plane, 0, 0, 1, everything), vec3(1, 0, 0), vec3(1, 2, 2));
    check_box(clip_to_slab(in_plane, 0, 1, 1, everything), vec3(1, 0, 0), vec3(1, 2, 2));
    CHECK(clip_to_slab(in_plane, 0, 1.5f, 2, everything).is_empty());
    const triangle touching{vec3(0, 0, 0), vec3(1, 1, 0), vec3(0, 2, 0)};  // meets x = 1 in one corner
    check_box(clip_to_slab(touching, 0, 1, 2, everything), vec3(1, 1, 0), vec3(1, 1, 0));
    const triangle line{vec3(0, 0, 0), vec3(2, 2, 0), vec3(1, 1, 0)};  // zero area
    check_box(clip_to_slab(line, 0, 0.5f, 1.5f, everything), vec3(0.5f, 0.5f, 0), vec3(1.5f, 1.5f, 0));
    const triangle point{vec3(3, 3, 3), vec3(3, 3, 3), vec3(3, 3, 3)};
    check_box(clip_to_slab(point, 1, 2, 3, everything), vec3(3, 3, 3), vec3(3, 3, 3));
    CHECK(clip_to_slab(point, 1, 3.5f, 4, everything).is_empty());
}

TEST_CASE("09.1 clip: random triangles and slabs hold the exact part, and barely more", "[ch09][pts:1]") {
    pcg32 g(9);
    std::size_t wrong = 0, nonempty = 0;
    for (int i = 0; i < 3000; ++i) {
        const float scale = i % 3 == 0 ? 1e6f : i % 3 == 1 ? 1.0f : 1e-3f;
        const triangle t = test::random_triangle(g, -scale, scale);
        const int axis = i % 3;
        float lo = (g.next_float() * 2 - 1) * scale, hi = (g.next_float() * 2 - 1) * scale;
        if (lo > hi) std::swap(lo, hi);
        if (i % 7 == 0) lo = -INFINITY;
        if (i % 11 == 0) hi = INFINITY;
        aabb box = t.bounds();
        if (i % 2 == 0) box.max[(axis + 1) % 3] = box.min[(axis + 1) % 3] + 0.6f * box.extent()[(axis + 1) % 3];
        const test::exact_box want = test::exact_clip(t, axis, lo, hi, box);
        const aabb got = clip_to_slab(t, axis, lo, hi, box);
        if (want.empty) {
            // Empty even within a box grown by rounding's reach: then nothing may be left.
            const long double r = 1e-6L * scale;
            const aabb grown{box.min - vec3(float(r)), box.max + vec3(float(r))};
            if (test::exact_clip(t, axis, lo, hi, grown).empty) wrong += !got.is_empty();
            continue;
        }
        ++nonempty;
        const long double tol = 1e-6L * scale;  // rounding: far below the triangle's size
        bool ok = !got.is_empty();
        for (int a = 0; a < 3 && ok; ++a)
            ok = got.min[a] <= want.min[a] + tol && got.max[a] >= want.max[a] - tol &&  // holds the part
                 got.min[a] >= want.min[a] - tol && got.max[a] <= want.max[a] + tol &&  // and barely more
                 got.min[a] >= box.min[a] && got.max[a] <= box.max[a];                  // within the box
        if (!ok && ++wrong <= 3) FAIL_CHECK("triangle " << i << " on axis " << axis << ": the box is wrong");
    }
    CHECK(wrong == 0);
    CHECK(nonempty > 1000);
}

TEST_CASE("09.1 clip: the box holds the exact part, rounded outwards, not to nearest", "[ch09][pts:1]") {
    // Crossing points at y = 0.1 (float(0.1) lies above it) and y = 0.7 (float(0.7) lies below it): rounded
    // to nearest, the box would miss a sliver of the part (0.1 to float(0.1), float(0.7) to 0.7), and a ray
    // through it would lose its hit. Rounded outwards, the box takes the float on the far side of each.
    const float below_tenth = 0x1.999998p-4f, above_seven_tenths = 0x1.666668p-1f;
    REQUIRE((double(0.1f) > 0.1 && double(below_tenth) < 0.1));       // the rounding the case relies on
    REQUIRE((double(0.7f) < 0.7 && double(above_seven_tenths) > 0.7));
    // The same two cases on every axis: the corners' coordinates turned by `axis` places.
    for (int axis = 0; axis < 3; ++axis) {
        const auto turn = [&](vec3 p) {
            vec3 q;
            for (int a = 0; a < 3; ++a) q[(a + axis) % 3] = p[a];
            return q;
        };
        INFO("clipped on axis " << axis);
        // (0,0,0), (10,1,0), (0,1,0) for 1 <= x <= 10: corners (1,0.1,0), (10,1,0), (1,1,0).
        const triangle low{turn(vec3(0, 0, 0)), turn(vec3(10, 1, 0)), turn(vec3(0, 1, 0))};
        check_box(clip_to_slab(low, axis, 1, 10, everything), turn(vec3(1, below_tenth, 0)), turn(vec3(10, 1, 0)));
        // (0,0,0), (10,0,7), (10,0,0) for 0 <= x <= 1: corners (0,0,0), (1,0,0.7), (1,0,0).
        const triangle high{turn(vec3(0, 0, 0)), turn(vec3(10, 0, 7)), turn(vec3(10, 0, 0))};
        check_box(clip_to_slab(high, axis, 0, 1, everything), turn(vec3(0, 0, 0)), turn(vec3(1, 0, above_seven_tenths)));
    }
    // Random triangles and slabs: the box holds the exact part (a clipper in long double), with no
    // tolerance at all, on every axis, at every scale.
    pcg32 g(91);
    std::size_t lost = 0, nonempty = 0;
    for (int i = 0; i < 3000; ++i) {
        const float scale = i % 3 == 0 ? 1e6f : i % 3 == 1 ? 1.0f : 1e-3f;
        const triangle t = test::random_triangle(g, -scale, scale);
        const int axis = (i / 3) % 3;
        float lo = (g.next_float() * 2 - 1) * scale, hi = (g.next_float() * 2 - 1) * scale;
        if (lo > hi) std::swap(lo, hi);
        const test::exact_box want = test::exact_clip(t, axis, lo, hi, everything);
        if (want.empty) continue;
        ++nonempty;
        const aabb got = clip_to_slab(t, axis, lo, hi, everything);
        bool holds = !got.is_empty();
        for (int a = 0; a < 3 && holds; ++a) holds = got.min[a] <= want.min[a] && got.max[a] >= want.max[a];
        if (!holds && ++lost <= 3)
            FAIL_CHECK(std::hexfloat << "triangle " << i << " on axis " << axis << ": [" << got.min.x << " " << got.min.y
                                     << " " << got.min.z << "] - [" << got.max.x << " " << got.max.y << " "
                                     << got.max.z << "] misses part of the exact part");
    }
    CHECK(lost == 0);
    CHECK(nonempty > 1000);
}
