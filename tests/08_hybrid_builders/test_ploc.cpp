// Chapter 08's PLOC (0 points): a valid binary tree on scenes and degenerate inputs (none, one, two and
// three primitives, copies, equal centroids, a far outlier, non-finite vertices); few rounds where all
// boxes are equal; the same tree as a plain serial transcription of the paper's loop, and on 1 and 2
// threads; the radius against the binary SAH cost; and chapter 05's fast walk over its flattened tree with
// brute force's answers bit for bit.
#include "strahl/ch05/accel.hpp"
#include "strahl/ch07/lbvh.hpp"
#include "strahl/ch07/morton.hpp"
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/ch08/ploc.hpp"
#include "strahl/parallel.hpp"
#include "strahl/procedural.hpp"
#include "strahl/rng.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include "flat_bvh_check.hpp"
#include "test_support.hpp"
#include "builder_inputs.hpp"
#include <catch2/catch.hpp>
#include <limits>
#include <map>

using namespace strahl;
using namespace strahl::ch08;

namespace {

using test::hard_meshes;
using test::same_tree;

// Step a of a round, plainly: per position the nearest within r positions, the same distance and tie order
// (a key per pair: gap, parity of the lower position, lower position).
std::vector<std::size_t> plain_nearest(const std::vector<aabb>& boxes, std::size_t r) {
    const std::size_t m = boxes.size();
    std::vector<std::size_t> nn(m);
    for (std::size_t i = 0; i < m; ++i) {
        float best = std::numeric_limits<float>::infinity();
        std::uint64_t best_key = ~std::uint64_t(0);
        for (std::size_t j = i > r ? i - r : 0; j <= std::min(m - 1, i + r); ++j) {
            if (j == i) continue;
            const aabb u = unite(boxes[i], boxes[j]);
            const vec3 e = u.max - u.min;
            const float area = e.x * e.y + e.y * e.z + e.z * e.x;  // half the area, inf and NaN as FLT_MAX
            const float d = area < std::numeric_limits<float>::max() ? area : std::numeric_limits<float>::max();
            const std::uint64_t lo = std::min(i, j), key = (std::max(i, j) - lo) << 33 | (lo & 1) << 32 | lo;
            if (d < best || (d == best && key < best_key)) best = d, best_key = key, nn[i] = j;
        }
    }
    return nn;
}

// The paper's loop written plainly, serially, one cluster at a time, every distance of a cluster's window
// computed afresh: the same Morton order, distance and tie order (a key per pair: gap, parity of the lower
// position, lower position), leaves 0..n-1 and inner nodes numbered as they are made.
binary_tree plain_ploc(const ch07::builder_inputs& in, std::size_t r) {
    ch07::morton_codes codes = ch07::compute_morton_codes(in.boxes, in.centroids, 10);
    ch07::radix_sort_params sort;
    sort.key_bits = 30;
    ch07::radix_sort(codes.keys, codes.ids, sort);
    binary_tree t;
    t.loose = codes.loose;
    std::vector<std::uint32_t> cluster;
    for (std::size_t k = 0; k < codes.ids.size(); ++k) {
        tree_node leaf;
        leaf.box = in.boxes[codes.ids[k]], leaf.prim = codes.ids[k];
        t.nodes.push_back(leaf);
        cluster.push_back(std::uint32_t(k));
    }
    while (cluster.size() > 1) {
        const std::size_t m = cluster.size();
        std::vector<aabb> boxes;
        for (const std::uint32_t c : cluster) boxes.push_back(t.nodes[c].box);
        const std::vector<std::size_t> nn = plain_nearest(boxes, r);
        std::vector<std::uint32_t> next;
        for (std::size_t i = 0; i < m; ++i) {
            const std::size_t j = nn[i];
            if (nn[j] != i) {
                next.push_back(cluster[i]);
            } else if (i < j) {
                tree_node parent;
                parent.left = cluster[i], parent.right = cluster[j];
                parent.box = unite(t.nodes[cluster[i]].box, t.nodes[cluster[j]].box);
                t.nodes.push_back(parent);
                const auto index = std::uint32_t(t.nodes.size() - 1);
                t.nodes[cluster[i]].parent = t.nodes[cluster[j]].parent = index;
                next.push_back(index);
            }
        }
        cluster.swap(next);
    }
    t.root = cluster.empty() ? none : cluster[0];
    return t;
}

std::unique_ptr<ch04::bvh_accel_base> ploc_accel(const ploc_params& p) {
    return ch05::make_bvh_accel(false, "ch08-" + to_string(p) + "-fast", [p](std::span<const aabb> b, std::span<const vec3> c) {
        return flatten(build_ploc(b, c, p));
    }, ch05::walk_kind::fast);
}

}  // namespace

TEST_CASE("ch08 PLOC: a valid binary tree on scenes and degenerate inputs", "[ch08]") {
    for (const auto& [name, mesh] : hard_meshes()) {
        const ch07::builder_inputs in(mesh);
        std::size_t loose = 0;
        for (std::size_t i = 0; i < in.boxes.size(); ++i) loose += !ch04::fits_in_tree(in.boxes[i], in.centroids[i]);
        for (const int radius : {1, 16}) {
            ploc_params p;
            p.radius = radius;
            INFO(name << ", " << to_string(p));
            ploc_report r;
            const binary_tree t = build_ploc(in.boxes, in.centroids, p, &r);
            CHECK(check_tree(t, in.boxes) == "");
            CHECK(t.leaves() * (t.root != none) + t.loose.size() == in.boxes.size());
            test::check_flat_bvh(flatten(t), in.boxes, in.centroids);
            CHECK(t.loose.size() == loose);
            if (name == "non-finite vertices") CHECK(loose >= 1);
            // Equal boxes pair up (0,1), (2,3), ...: the list halves every round, log2(3000) rounds and
            // a few, not one merge per round.
            if (name == "3000 identical triangles") CHECK(r.iterations <= 13);
        }
    }
    ploc_params wide;
    wide.bits_per_axis = 21;
    const ch07::builder_inputs in(random_soup(2000, 3, 0.05f));
    CHECK(check_tree(build_ploc(in.boxes, in.centroids, wide), in.boxes) == "");
}

TEST_CASE("ch08 PLOC: the same tree as the paper's loop written plainly", "[ch08]") {
    triangle_mesh outlier = random_soup(1500, 6, 0.1f);
    const auto b = std::uint32_t(outlier.positions.size());
    outlier.positions.insert(outlier.positions.end(), {vec3(1e30f), vec3(1e30f, 0, 0), vec3(0, 1e30f, 0)});
    outlier.indices.push_back(uvec3(b, b + 1, b + 2));
    for (const triangle_mesh& m : {builtin_scene("teapot").mesh, random_soup(5000, 5, 0.05f),
                                   test::copies(700, vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)), outlier}) {
        const ch07::builder_inputs in(m);
        for (const int radius : {1, 3, 16, 100}) {
            ploc_params p;
            p.radius = radius;
            INFO(m.triangle_count() << " triangles, " << to_string(p));
            CHECK(same_tree(build_ploc(in.boxes, in.centroids, p), plain_ploc(in, std::size_t(radius))));
        }
    }
}

TEST_CASE("ch08 PLOC: the same tree on 1 and 2 threads", "[ch08]") {
    for (const triangle_mesh& m : {builtin_scene("teapot_stadium").mesh, random_soup(20000, 5, 0.02f)}) {
        const ch07::builder_inputs in(m);
        for (const int radius : {1, 16}) {
            ploc_params p;
            p.radius = radius;
            binary_tree one, two;
            {
                const thread_limit limit(1);
                one = build_ploc(in.boxes, in.centroids, p);
            }
            {
                const thread_limit limit(2);
                two = build_ploc(in.boxes, in.centroids, p);
            }
            INFO(m.triangle_count() << " triangles, " << to_string(p));
            REQUIRE(check_tree(one, in.boxes) == "");
            CHECK(same_tree(one, two));
        }
    }
}

// What the radius buys, measured (release build): the binary SAH cost for radius 1, 2, 4, 8, 16
//   teapot  26.60 25.65 25.37 25.26 25.42  (chapter 07's LBVH 27.38)
//   soup    85.22 83.60 83.67 85.15 85.69  (LBVH 86.39)
// On the teapot it falls by 4.4% from 1 to 16, nearly all of it by radius 4; on the uniform soup, where no
// merge is much better than its neighbours', radius 2 and 4 are best and 16 is 0.5% above 1 (the plain
// loop above gives the same trees: the greedy merges, not the code). Asserted: what holds with margin.
TEST_CASE("ch08 PLOC: the SAH cost against the radius", "[ch08]") {
    std::map<std::string, std::vector<double>> cost;
    std::map<std::string, double> lbvh;
    for (const std::string name : {"soup", "teapot"}) {
        const ch07::builder_inputs in(builtin_scene(name).mesh);
        for (const int radius : {1, 2, 4, 8, 16}) {
            ploc_params p;
            p.radius = radius;
            cost[name].push_back(binary_sah_cost(build_ploc(in.boxes, in.centroids, p)));
        }
        lbvh[name] = binary_sah_cost(lbvh_binary_tree(in.boxes, in.centroids));
        const std::vector<double>& c = cost[name];
        WARN(name << ": binary SAH cost, radius 1 2 4 8 16: " << c[0] << " " << c[1] << " " << c[2] << " " << c[3]
                  << " " << c[4] << " (LBVH " << lbvh[name] << ")");
        INFO(name);
        for (const double k : c) CHECK(k < lbvh[name]);      // every radius beats the LBVH
        CHECK(c[2] < c[0] * 0.985);                           // radius 4 below radius 1, by 1.5% or more
        for (const double k : c) CHECK(k <= c[0] * 1.01);    // no radius more than 1% above radius 1
    }
    const std::vector<double>& teapot = cost["teapot"];
    CHECK(teapot[4] < teapot[0] * 0.97);  // on the teapot radius 16 is 3% or more below radius 1
    for (std::size_t k = 1; k < teapot.size(); ++k) CHECK(teapot[k] <= teapot[k - 1] * 1.01);  // no step rises 1%
}

TEST_CASE("ch08 PLOC: chapter 05's fast walk over the flattened tree equals brute force", "[ch08][adversarial]") {
    // The bunny with fewer rays: brute force over its 69,451 triangles costs 1.5 s per 1000 rays here.
    const auto meshes = test::exactness_meshes();
    for (const auto& [name, m] : meshes)
        for (const int radius : {1, 16}) {
            if (name == "bunny" && radius == 1) continue;  // brute force over 69,451 triangles: once is enough
            ploc_params p;
            p.radius = radius;
            const auto a = ploc_accel(p);
            a->build(test::mesh_only(m));
            INFO(a->name() << " on " << name);
            CHECK(test::disagreements_with_brute_force(*a, m, test::nasty_rays(a->tree(), name == "bunny" ? 600 : 2000, 21)) == 0);
        }
}

TEST_CASE("ch08 PLOC: one round's nearest neighbours (the figure's step) as the plain loop finds them", "[ch08]") {
    pcg32 g(8, 3);
    std::vector<aabb> boxes;
    for (int i = 0; i < 300; ++i) {
        const vec3 p(g.next_float() * 10.0f, g.next_float() * 10.0f, g.next_float());
        boxes.push_back({p, p + vec3(0.2f + g.next_float(), 0.3f, 0.1f + g.next_float())});
        if (i % 7 == 0) boxes.push_back(boxes.back());  // copies: ties broken by the order on pairs
    }
    for (const int r : {1, 2, 5, 16, 300}) {
        const std::vector<std::uint32_t> nn = ploc_nearest_neighbours(boxes, r);
        const std::vector<std::size_t> expected = plain_nearest(boxes, std::size_t(std::min(r, 256)));
        REQUIRE(nn.size() == boxes.size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < nn.size(); ++i) differ += nn[i] != expected[i];
        INFO("radius " << r);
        CHECK(differ == 0);
    }
    CHECK_THROWS_AS(ploc_nearest_neighbours(std::vector<aabb>(1), 2), std::invalid_argument);
}
