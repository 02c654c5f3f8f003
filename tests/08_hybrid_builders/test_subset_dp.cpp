// Exercise 08.2 the subset DP (10 points): subset_costs on one to four leaves worked out by hand (boxes
// along x), with other constants and leaf costs; every subset's cost against brute force over every binary
// tree of its leaves (n <= 5: up to 105 trees); and the partitions: each a proper subset reaching the
// minimum, together a tree that costs what cost[full] says.
#include "strahl/ch08/treelet.hpp"
#include "strahl/rng.hpp"
#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <limits>
#include <vector>

using namespace strahl;
using namespace strahl::ch08;

namespace {

// A unit box along x at x: [x, x + 1] x [0, 1] x [0, 1]; the union of such boxes from a to b has area
// 4 (b - a) + 2.
aabb unit_at(float x) { return {vec3(x, 0, 0), vec3(x + 1, 1, 1)}; }

float area_of(std::span<const aabb> boxes, unsigned set) {
    aabb b;
    for (unsigned k = 0; k < boxes.size(); ++k)
        if (set >> k & 1) b.grow(boxes[k]);
    return b.surface_area();
}

// Brute force: every binary tree over the leaves of `set`, built by inserting the leaves one at a time
// beside any node of the tree so far ((2m - 3)!! trees for m leaves), each priced from scratch:
// C_T * (sum of its inner nodes' areas) + the leaf costs. Returns the least.
struct brute_force {
    std::span<const aabb> boxes;
    std::span<const float> leaf_costs;
    float c_t;
    struct node { int left = -1, right = -1, leaf = -1; };
    std::vector<node> nodes;
    int root = -1;
    double best = std::numeric_limits<double>::infinity();

    aabb box(int i) const {
        return nodes[i].leaf >= 0 ? boxes[nodes[i].leaf] : unite(box(nodes[i].left), box(nodes[i].right));
    }
    double price(int i) const {
        if (nodes[i].leaf >= 0) return leaf_costs[nodes[i].leaf];
        return c_t * double(box(i).surface_area()) + price(nodes[i].left) + price(nodes[i].right);
    }
    void insert(const std::vector<int>& leaves, std::size_t next) {
        if (next == leaves.size()) {
            best = std::min(best, price(root));
            return;
        }
        const int count = int(nodes.size());
        for (int at = 0; at < count; ++at) {
            // A new inner node takes `at`'s place, with `at` and the new leaf as its children.
            const int leaf = int(nodes.size()), inner = leaf + 1;
            nodes.push_back({-1, -1, leaves[next]});
            nodes.push_back({at, leaf, -1});
            int parent = -1, side = 0;
            for (int p = 0; p < count; ++p)
                if (nodes[p].left == at) parent = p, side = 0;
                else if (nodes[p].right == at) parent = p, side = 1;
            const int old_root = root;
            if (parent < 0) root = inner;
            else (side == 0 ? nodes[parent].left : nodes[parent].right) = inner;
            insert(leaves, next + 1);
            if (parent < 0) root = old_root;
            else (side == 0 ? nodes[parent].left : nodes[parent].right) = at;
            nodes.resize(std::size_t(count));
        }
    }
    double least(unsigned set) {
        std::vector<int> leaves;
        for (int k = 0; k < int(boxes.size()); ++k)
            if (set >> k & 1) leaves.push_back(k);
        nodes = {{-1, -1, leaves[0]}};
        root = 0;
        best = std::numeric_limits<double>::infinity();
        insert(leaves, 1);
        return best;
    }
};

struct instance {
    std::vector<aabb> boxes;
    std::vector<float> costs;
};

// n random boxes in the unit cube (sizes up to `size`), leaf costs C_I * area plus a random subtree part.
instance random_instance(int n, std::uint64_t seed, float size) {
    pcg32 g(seed);
    instance in;
    for (int k = 0; k < n; ++k) {
        const vec3 p(g.next_float(), g.next_float(), g.next_float());
        const vec3 e = size * vec3(g.next_float(), g.next_float(), g.next_float());
        in.boxes.push_back({p, p + e});
        in.costs.push_back(in.boxes.back().surface_area() * (1.0f + 3.0f * g.next_float()));
    }
    return in;
}

// The tree the partitions describe, priced from its boxes: C_T * (sum of inner areas) + the leaf costs.
double tree_of_partitions(const optimal_topology& t, std::span<const aabb> boxes, std::span<const float> costs,
                          float c_t, unsigned set, int& inner_nodes) {
    if (std::has_single_bit(set)) return costs[unsigned(std::countr_zero(set))];
    const unsigned p = t.partition[set];
    REQUIRE(p != 0);
    REQUIRE((p & ~set) == 0);
    REQUIRE(p != set);
    ++inner_nodes;
    return c_t * double(area_of(boxes, set)) + tree_of_partitions(t, boxes, costs, c_t, p, inner_nodes) +
           tree_of_partitions(t, boxes, costs, c_t, set ^ p, inner_nodes);
}

}  // namespace

TEST_CASE("08.2 subset DP: one, two and three leaves by hand", "[ch08][pts:2]") {
    const ch05::sah_costs c;  // C_T = C_I = 1
    // One leaf: its cost as given.
    const std::vector<aabb> one = {unit_at(0)};
    const std::vector<float> one_cost = {3.5f};
    CHECK(subset_costs(one, one_cost, c).cost[1] == Approx(3.5f));
    // Two leaves at x = 0 and 3: the union [0, 4] has area 18; leaf costs 6 each: 30.
    const std::vector<aabb> two = {unit_at(0), unit_at(3)};
    const std::vector<float> sixes = {6, 6, 6, 6};
    const optimal_topology t2 = subset_costs(two, std::span(sixes).first(2), c);
    CHECK(t2.cost[1] == Approx(6));
    CHECK(t2.cost[2] == Approx(6));
    CHECK(t2.cost[3] == Approx(30));
    CHECK((t2.partition[3] == 1 || t2.partition[3] == 2));
    // Three leaves at x = 0, 1, 5: pairs {0,1} 10 + 12, {1,5} 22 + 12, {0,5} 26 + 12; all three: area 26
    // plus the best of 22 + 6, 34 + 6, 38 + 6: the pair {0,1} beside leaf 2.
    const std::vector<aabb> three = {unit_at(0), unit_at(1), unit_at(5)};
    const optimal_topology t3 = subset_costs(three, std::span(sixes).first(3), c);
    CHECK(t3.cost[0b011] == Approx(22));
    CHECK(t3.cost[0b110] == Approx(34));
    CHECK(t3.cost[0b101] == Approx(38));
    CHECK(t3.cost[0b111] == Approx(54));
    CHECK((t3.partition[0b111] == 0b011 || t3.partition[0b111] == 0b100));
}

TEST_CASE("08.2 subset DP: four leaves by hand: two pairs beat every chain, and C_T scales, leaf costs add",
          "[ch08][pts:2]") {
    // Leaves at x = 0, 1, 10, 11: the pairs {0,1} and {10,11} cost 10 + 12 each, the whole box [0, 12] has
    // area 50: 50 + 22 + 22 = 94. Every chain costs more: (((0 1) 10) 11) is 50 + 46 + 10 + 24 = 130.
    const std::vector<aabb> four = {unit_at(0), unit_at(1), unit_at(10), unit_at(11)};
    const std::vector<float> sixes = {6, 6, 6, 6};
    const optimal_topology t = subset_costs(four, sixes, ch05::sah_costs{});
    CHECK(t.cost[0b0011] == Approx(22));
    CHECK(t.cost[0b1100] == Approx(22));
    CHECK(t.cost[0b0111] == Approx(74));   // [0, 11]: 46, plus {0,1} 22 and leaf 10's 6
    CHECK(t.cost[0b1011] == Approx(78));   // [0, 12]: 50, plus 22 + 6
    CHECK(t.cost[0b1111] == Approx(94));
    CHECK((t.partition[0b1111] == 0b0011 || t.partition[0b1111] == 0b1100));
    // C_T = 2 doubles the inner nodes' areas; leaf costs 1, 2, 3, 4 are what the leaves cost (C_I does not
    // enter: the leaves' costs are given): 2 (50 + 10 + 10) + 10 = 150.
    ch05::sah_costs c;
    c.traversal = 2.0f, c.intersection = 5.0f;
    const std::vector<float> costs = {1, 2, 3, 4};
    const optimal_topology u = subset_costs(four, costs, c);
    CHECK(u.cost[0b0001] == Approx(1));
    CHECK(u.cost[0b1000] == Approx(4));
    CHECK(u.cost[0b0011] == Approx(23));
    CHECK(u.cost[0b1100] == Approx(27));
    CHECK(u.cost[0b1111] == Approx(150));
    CHECK((u.partition[0b1111] == 0b0011 || u.partition[0b1111] == 0b1100));
}

TEST_CASE("08.2 subset DP: every subset's cost is the least of all its trees (brute force, 2 to 5 leaves)",
          "[ch08][pts:4]") {
    int instances = 0;
    for (int n = 2; n <= 5; ++n)
        for (std::uint64_t seed = 1; seed <= 12; ++seed)
            for (const float c_t : {1.0f, 0.3f}) {
                const instance in = random_instance(n, seed * 31 + std::uint64_t(n), seed % 3 == 0 ? 0.8f : 0.2f);
                ch05::sah_costs c;
                c.traversal = c_t;
                const optimal_topology t = subset_costs(in.boxes, in.costs, c);
                brute_force b{in.boxes, in.costs, c_t, {}, -1, 0.0};
                for (unsigned set = 1; set < (1u << n); ++set) {
                    INFO(n << " leaves, seed " << seed << ", C_T " << c_t << ", subset " << set);
                    CHECK(t.cost[set] == Approx(b.least(set)).epsilon(1e-5));
                }
                ++instances;
            }
    CHECK(instances == 96);
}

TEST_CASE("08.2 subset DP: each partition reaches the minimum, and together they describe a tree of that cost",
          "[ch08][pts:2]") {
    for (int n = 2; n <= max_dp_leaves; ++n)
        for (std::uint64_t seed = 1; seed <= 6; ++seed) {
            const instance in = random_instance(n, seed * 7 + std::uint64_t(n) * 1000, 0.4f);
            ch05::sah_costs c;
            c.traversal = seed % 2 ? 1.0f : 1.7f;
            const optimal_topology t = subset_costs(in.boxes, in.costs, c);
            for (unsigned set = 1; set < (1u << n); ++set) {
                INFO(n << " leaves, seed " << seed << ", subset " << set);
                if (std::has_single_bit(set)) {
                    CHECK(t.cost[set] == Approx(in.costs[unsigned(std::countr_zero(set))]));
                    continue;
                }
                const unsigned p = t.partition[set];
                REQUIRE(p != 0);
                REQUIRE((p & ~set) == 0);  // within the set
                REQUIRE(p != set);         // a proper subset
                const float area = c.traversal * area_of(in.boxes, set);
                CHECK(t.cost[set] == Approx(area + t.cost[p] + t.cost[set ^ p]).epsilon(1e-5));
                // No other partition does better.
                for (unsigned q = (set - 1) & set; q != 0; q = (q - 1) & set)
                    CHECK(t.cost[set] <= area + t.cost[q] + t.cost[set ^ q] + 1e-5f * t.cost[set]);
            }
            const unsigned full = (1u << n) - 1;
            int inner = 0;
            const double priced = tree_of_partitions(t, in.boxes, in.costs, c.traversal, full, inner);
            CHECK(inner == n - 1);
            CHECK(t.cost[full] == Approx(priced).epsilon(1e-5));
        }
}
