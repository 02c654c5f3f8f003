// Exercise 05.2 bin assignment (5 points). Only bin_index, on hand-made mappings.
#include "strahl/ch05/sah.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

using namespace strahl;
using namespace strahl::ch05;

TEST_CASE("05.2 bin assignment: equal-width bins over the centroid box", "[ch05][pts:2]") {
    const bin_mapping m = make_bin_mapping(0.0f, 8.0f, 8);  // bin b covers [b, b + 1)
    CHECK(bin_index(m, 0.0f) == 0);
    CHECK(bin_index(m, 0.99f) == 0);
    CHECK(bin_index(m, 1.0f) == 1);
    CHECK(bin_index(m, 3.5f) == 3);
    CHECK(bin_index(m, 7.25f) == 7);
    const bin_mapping n = make_bin_mapping(-2.0f, 2.0f, 4);  // bins of width 1 from -2
    CHECK(bin_index(n, -1.5f) == 0);
    CHECK(bin_index(n, -0.5f) == 1);
    CHECK(bin_index(n, 0.0f) == 2);
    CHECK(bin_index(n, 1.9f) == 3);
}

TEST_CASE("05.2 bin assignment: the clamp at the top bin, below the bottom, and NaN", "[ch05][pts:3]") {
    const bin_mapping m = make_bin_mapping(0.0f, 8.0f, 8);
    CHECK(bin_index(m, 8.0f) == 7);  // hi itself: k before the clamp
    CHECK(bin_index(m, std::nextafter(8.0f, 0.0f)) == 7);
    CHECK(bin_index(m, 1e30f) == 7);  // far beyond int's range before the clamp
    CHECK(bin_index(m, std::numeric_limits<float>::infinity()) == 7);
    CHECK(bin_index(m, -1.0f) == 0);
    CHECK(bin_index(m, -1e30f) == 0);
    CHECK(bin_index(m, std::numeric_limits<float>::quiet_NaN()) == 0);
    // Rounding: with k / (hi - lo) not exact, a centroid just below hi can compute to k.
    for (const float hi : {0.1f, 0.3f, 0.7f, 1.1f, 3.3f, 1e7f}) {
        const bin_mapping r = make_bin_mapping(0.0f, hi, 7);
        INFO("7 bins over [0, " << hi << "]");
        CHECK(bin_index(r, hi) == 6);
        CHECK(bin_index(r, std::nextafter(hi, 0.0f)) == 6);
    }
    // 256 bins, every bin reachable and in order.
    const bin_mapping w = make_bin_mapping(10.0f, 11.0f, 256);
    int last = -1, first_bad = -1, bad_bin = 0, bin_before = 0;
    bool in_order = true;
    for (int i = 0; i <= 2560; ++i) {
        const int b = bin_index(w, 10.0f + float(i) / 2560.0f);
        const bool ok = b >= last && b >= 0 && b < 256;
        if (!ok && in_order) first_bad = i, bad_bin = b, bin_before = last;
        in_order = in_order && ok;
        last = b;
    }
    {
        INFO("256 bins over [10, 11]: first out of order or out of [0, 256) at centroid 10 + " << first_bad
             << "/2560: bin " << bad_bin << " after bin " << bin_before);
        CHECK(in_order);
    }
    CHECK(last == 255);
}
