// Exercise 03.2 classify (5 points). Only classify, on hand-made boxes against the plane y = 2.
#include "strahl/ch03/sah.hpp"
#include <catch2/catch.hpp>
#include <string>

using namespace strahl;
using namespace strahl::ch03;

// A side prints by name in a failing check ("both == left"), not as its number.
namespace Catch {
template <>
struct StringMaker<strahl::ch03::side> {
    static std::string convert(strahl::ch03::side s) {
        switch (s) {
            case strahl::ch03::side::left: return "left";
            case strahl::ch03::side::right: return "right";
            case strahl::ch03::side::both: return "both";
        }
        return "side " + std::to_string(int(s));
    }
};
}  // namespace Catch

namespace {
aabb y_range(float lo, float hi) { return aabb{vec3(-1, lo, 5), vec3(1, hi, 6)}; }
}  // namespace

TEST_CASE("03.2 classify: boxes wholly on one side, also when touching the plane", "[ch03][pts:2]") {
    CHECK(classify(y_range(0, 1), 1, 2.0f, true) == side::left);
    CHECK(classify(y_range(0, 1), 1, 2.0f, false) == side::left);
    CHECK(classify(y_range(3, 4), 1, 2.0f, true) == side::right);
    CHECK(classify(y_range(0, 2), 1, 2.0f, false) == side::left);   // ends on the plane
    CHECK(classify(y_range(2, 4), 1, 2.0f, true) == side::right);   // starts on it
    // Only the plane's axis counts: the same box against x = 0 straddles.
    CHECK(classify(y_range(0, 1), 0, 0.0f, true) == side::both);
    CHECK(classify(y_range(0, 1), 2, 6.0f, false) == side::left);
}

TEST_CASE("03.2 classify: a box across the plane is a reference in both children", "[ch03][pts:1]") {
    CHECK(classify(y_range(1, 3), 1, 2.0f, true) == side::both);
    CHECK(classify(y_range(1.999f, 2.001f), 1, 2.0f, false) == side::both);
}

TEST_CASE("03.2 classify: a planar box goes where planar_left says, only when it lies in the plane",
          "[ch03][pts:2]") {
    CHECK(classify(y_range(2, 2), 1, 2.0f, true) == side::left);
    CHECK(classify(y_range(2, 2), 1, 2.0f, false) == side::right);
    // Flat but elsewhere: an ordinary box.
    CHECK(classify(y_range(1, 1), 1, 2.0f, false) == side::left);
    CHECK(classify(y_range(3, 3), 1, 2.0f, true) == side::right);
}
