// Exercise 04.2 the split of BUILD-HIERARCHY (8 points). Only partition_split, on hand-made centroids.
#include "strahl/ch04/bvh.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <numeric>
#include <sstream>
#include <string>

using namespace strahl;
using namespace strahl::ch04;

namespace {
std::vector<std::uint32_t> iota(std::size_t n, std::uint32_t from = 0) {
    std::vector<std::uint32_t> v(n);
    std::iota(v.begin(), v.end(), from);
    return v;
}
std::string list(const std::vector<std::uint32_t>& ids) {
    std::ostringstream out;
    for (std::size_t i = 0; i < ids.size(); ++i) out << (i ? ", " : "{") << ids[i];
    out << "}";
    return out.str();
}
// Every entry left of mid has a centroid <= every entry right of it, on axis; and ids is a permutation.
void check_partitioned(std::vector<std::uint32_t> ids, const std::vector<vec3>& c, int axis, std::size_t mid,
                       const std::vector<std::uint32_t>& before) {
    INFO("ids after partition_split " << list(ids) << ", mid " << mid << ", axis " << axis);
    for (std::size_t i = 0; i < mid; ++i)
        for (std::size_t j = mid; j < ids.size(); ++j) {
            INFO("ids[" << i << "] = " << ids[i] << " is left of mid, ids[" << j << "] = " << ids[j] << " right of it");
            CHECK(c[ids[i]][axis] <= c[ids[j]][axis]);
        }
    std::sort(ids.begin(), ids.end());
    std::vector<std::uint32_t> b = before;
    std::sort(b.begin(), b.end());
    CHECK(ids == b);
}
}  // namespace

TEST_CASE("04.2 partition: the object median along the longest axis of the centroid box", "[ch04][pts:3]") {
    // Centroids spread 10 on y, 1 on x and z: y is the axis. Shuffled order.
    std::vector<vec3> c;
    const float ys[] = {7, 2, 9, 0, 5, 3, 8, 1, 6, 4};
    for (int i = 0; i < 10; ++i) c.push_back(vec3(0.1f * float(i % 3), ys[i], 0.05f * float(i % 2)));
    std::vector<std::uint32_t> ids = iota(10);
    const auto before = ids;
    const split_result s = partition_split(ids, c, split_method::object_median);
    CHECK(s.axis == 1);
    CHECK(s.mid == 5u);
    check_partitioned(ids, c, 1, s.mid, before);
    // An odd count, and a range naming only some of the centroids.
    std::vector<std::uint32_t> some = {9, 3, 0, 6, 2};
    const auto some_before = some;
    const split_result t = partition_split(some, c, split_method::object_median);
    CHECK(t.axis == 1);
    CHECK(t.mid == 2u);
    check_partitioned(some, c, 1, t.mid, some_before);
}

TEST_CASE("04.2 partition: the spatial median cuts the centroid box in the middle", "[ch04][pts:3]") {
    // On x: 0, 0.1, 0.2, 0.3 and 10: the middle 5 leaves four left, one right (the object median: 2 and 3).
    std::vector<vec3> c = {vec3(0.2f, 0, 0), vec3(10, 0, 0), vec3(0, 0, 0), vec3(0.3f, 0, 0), vec3(0.1f, 0, 0)};
    std::vector<std::uint32_t> ids = iota(5);
    const split_result s = partition_split(ids, c, split_method::spatial_median);
    CHECK(s.axis == 0);
    CHECK(s.mid == 4u);
    check_partitioned(ids, c, 0, s.mid, iota(5));
    CHECK(ids[4] == 1u);
    // The same with the object median.
    std::vector<std::uint32_t> ids2 = iota(5);
    const split_result o = partition_split(ids2, c, split_method::object_median);
    CHECK(o.mid == 2u);
    check_partitioned(ids2, c, 0, o.mid, iota(5));
    // Centroids on z only, all but one at the low end: still a split with both sides non-empty.
    std::vector<vec3> z = {vec3(0, 0, 1), vec3(0, 0, 0), vec3(0, 0, 0), vec3(0, 0, 0)};
    std::vector<std::uint32_t> idz = iota(4);
    const split_result sz = partition_split(idz, z, split_method::spatial_median);
    CHECK(sz.axis == 2);
    CHECK(sz.mid == 3u);
    CHECK(idz[3] == 0u);
}

TEST_CASE("04.2 partition: all centroids equal split in half, untouched", "[ch04][pts:2]") {
    for (const split_method m : {split_method::object_median, split_method::spatial_median}) {
        INFO((m == split_method::object_median ? "object median" : "spatial median") << " split");
        const std::vector<vec3> c(7, vec3(0.5f, -2.0f, 3.0f));
        std::vector<std::uint32_t> ids = {6, 5, 4, 3, 2, 1, 0};
        const split_result s = partition_split(ids, c, m);
        CHECK(s.mid == 3u);
        CHECK(ids == std::vector<std::uint32_t>{6, 5, 4, 3, 2, 1, 0});
        std::vector<std::uint32_t> two = {1, 0};
        CHECK(partition_split(two, c, m).mid == 1u);
    }
}
