// BUILD-LBVH: codes, sort, hierarchy, boxes bottom up, SAH collapse into chapter 04's flat node array.
//   C. Lauterbach et al., "Fast BVH construction on GPUs", Eurographics 2009;
//   T. Karras, "Maximizing parallelism in the construction of BVHs, octrees, and k-d trees", HPG 2012,
//   section 4 (the bottom-up pass with an atomic counter per node);
//   the collapse as in pbrt-v4's SAH termination rule and chapter 05 (C_I * N against the split's cost).
#include "strahl/ch07/lbvh.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch07/morton.hpp"
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/parallel.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace strahl::ch07 {

namespace {

// The bottom-up climb (Karras 2012, section 4): one task per leaf walks to the root; at each inner node the
// first of its two children to arrive stops, the second calls inner(node) (both children done: their
// results are visible, acquire/release on the counter) and climbs on.
template <class Inner>
void bottom_up(const radix_tree& t, Inner&& inner) {
    if (t.leaves() < 2) return;
    std::vector<std::uint32_t> arrivals(t.leaves() - 1, 0u);
    parallel_for_chunks(t.leaves(), 1024, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k)
            for (std::uint32_t node = t.leaf_parent[k]; node != radix_tree::none; node = t.parent[node]) {
                if (std::atomic_ref<std::uint32_t>(arrivals[node]).fetch_add(1, std::memory_order_acq_rel) == 0)
                    break;
                inner(node);
            }
    });
}

// The collapse: per inner node its SAH cost (not normalised: areas, not area ratios), whether it becomes
// a leaf, and its height as emitted (a collapsed node is a leaf: 0), then the depth-first emission.
struct collapser {
    const radix_tree& t;
    std::span<const aabb> leaf_boxes;       // per leaf: the box of primitive ids[k]
    const std::vector<aabb>& inner_boxes;   // per inner node
    const lbvh_params& p;
    ch04::bvh& out;
    lbvh_report& report;
    std::vector<float> cost;
    std::vector<std::uint8_t> as_leaf, height;
    std::vector<std::uint32_t> size;      // nodes the subtree is written as (a collapsed one: 1)
    std::vector<std::uint16_t> max_leaf;  // the largest leaf written below

    const aabb& box_of(std::uint32_t ref) const {
        return is_leaf_ref(ref) ? leaf_boxes[ref & ~leaf_bit] : inner_boxes[ref];
    }
    float cost_of(std::uint32_t ref) const {
        return is_leaf_ref(ref) ? p.costs.intersection * leaf_boxes[ref & ~leaf_bit].surface_area() : cost[ref];
    }
    int height_of(std::uint32_t ref) const { return is_leaf_ref(ref) ? 0 : height[ref]; }
    std::uint32_t size_of(std::uint32_t ref) const { return is_leaf_ref(ref) ? 1 : size[ref]; }
    std::uint16_t max_leaf_of(std::uint32_t ref) const { return is_leaf_ref(ref) ? 1 : max_leaf[ref]; }

    // 1. Bottom up: as it stands, C_T * A + the children's costs; as a leaf, C_I * N * A (N <= max_leaf).
    void price() {
        const std::size_t inner = t.left.size();
        cost.assign(inner, 0.0f), as_leaf.assign(inner, 0), height.assign(inner, 0);
        size.assign(inner, 1), max_leaf.assign(inner, 1);
        bottom_up(t, [&](std::uint32_t i) {
            const float area = inner_boxes[i].surface_area();
            const std::uint32_t n = t.last[i] - t.first[i] + 1;
            const float split = p.costs.traversal * area + cost_of(t.left[i]) + cost_of(t.right[i]);
            const float leaf = p.costs.intersection * float(n) * area;
            as_leaf[i] = n <= std::uint32_t(p.max_leaf) && leaf <= split;
            cost[i] = as_leaf[i] ? leaf : split;
            height[i] = as_leaf[i] ? 0 : std::uint8_t(std::min(255, 1 + std::max(height_of(t.left[i]), height_of(t.right[i]))));
            size[i] = as_leaf[i] ? 1 : 1 + size_of(t.left[i]) + size_of(t.right[i]);
            max_leaf[i] = as_leaf[i] ? std::uint16_t(n) : std::max(max_leaf_of(t.left[i]), max_leaf_of(t.right[i]));
        });
    }

    std::uint32_t push(const aabb& box, int depth) {
        ch04::bvh_node n{};
        for (int a = 0; a < 3; ++a) n.bmin[a] = box.min[a], n.bmax[a] = box.max[a];
        out.nodes.push_back(n);
        out.stats.depth = std::max(out.stats.depth, depth);
        return std::uint32_t(out.nodes.size() - 1);
    }
    void make_leaf(std::uint32_t index, std::uint32_t first, std::uint32_t count) {
        out.nodes[index].offset = first;
        out.nodes[index].count = std::uint16_t(count);
        ++out.stats.leaves;
        out.stats.max_leaf = std::max<std::size_t>(out.stats.max_leaf, count);
    }
    void make_inner(std::uint32_t index, std::uint32_t right) {
        out.nodes[index].offset = right;
        out.nodes[index].axis = std::uint8_t(out.nodes[index].box().largest_axis());
        ++out.stats.inner;
    }

    // 2'. Where no subtree reaches below max_depth, every subtree's place in the array is known from the
    //     sizes: the left child at index + 1, the right one after the left subtree's size(left) nodes. Large
    //     subtrees are then written in parallel, the two children of a node as two tasks.
    void write(std::uint32_t ref, std::uint32_t index) {
        ch04::bvh_node& node = out.nodes[index];
        const aabb& box = box_of(ref);
        for (int a = 0; a < 3; ++a) node.bmin[a] = box.min[a], node.bmax[a] = box.max[a];
        if (is_leaf_ref(ref)) {
            node.offset = ref & ~leaf_bit, node.count = 1;
            return;
        }
        if (as_leaf[ref]) {
            node.offset = t.first[ref], node.count = std::uint16_t(t.last[ref] - t.first[ref] + 1);
            return;
        }
        const std::uint32_t right = index + 1 + size_of(t.left[ref]);
        node.offset = right;
        node.axis = std::uint8_t(box.largest_axis());
        if (size[ref] >= 8192)
            parallel_invoke([&] { write(t.left[ref], index + 1); }, [&] { write(t.right[ref], right); });
        else
            write(t.left[ref], index + 1), write(t.right[ref], right);
    }
    // The whole tree by write(), with chapter 04's statistics from the sizes; false (nothing written) where
    // a subtree would reach below max_depth, for emit() to handle.
    bool write_all(std::uint32_t root) {
        if (height_of(root) > p.max_depth) return false;
        out.nodes.resize(size_of(root));
        write(root, 0);
        out.stats.depth = height_of(root);
        out.stats.leaves = (out.nodes.size() + 1) / 2;
        out.stats.inner = out.nodes.size() - out.stats.leaves;
        out.stats.max_leaf = max_leaf_of(root);
        return true;
    }

    // 2. Depth first, left child next. At depth max_depth - 32 a subtree that would reach below max_depth
    //    is emitted by halving its range instead (halve).
    std::uint32_t emit(std::uint32_t ref, int depth) {
        const std::uint32_t index = push(box_of(ref), depth);
        if (is_leaf_ref(ref)) {
            make_leaf(index, ref & ~leaf_bit, 1);
        } else if (as_leaf[ref]) {
            make_leaf(index, t.first[ref], t.last[ref] - t.first[ref] + 1);
        } else if (depth == p.max_depth - 32 && depth + height[ref] > p.max_depth) {
            ++report.rebalanced;
            out.nodes.pop_back();
            return halve(t.first[ref], t.last[ref], depth);
        } else {
            emit(t.left[ref], depth + 1);
            make_inner(index, emit(t.right[ref], depth + 1));
        }
        return index;
    }

    // Leaves [first, last] split at their middle until at most max_leaf remain: 32 levels at most.
    std::uint32_t halve(std::uint32_t first, std::uint32_t last, int depth) {
        aabb box;
        for (std::uint32_t k = first; k <= last; ++k) box.grow(leaf_boxes[k]);
        const std::uint32_t index = push(box, depth);
        if (last - first + 1 <= std::uint32_t(p.max_leaf)) {
            make_leaf(index, first, last - first + 1);
        } else {
            const std::uint32_t mid = first + (last - first) / 2;
            halve(first, mid, depth + 1);
            make_inner(index, halve(mid + 1, last, depth + 1));
        }
        return index;
    }
};

}  // namespace

std::string to_string(const lbvh_params& p) {
    return std::string(p.hierarchy == hierarchy_method::karras ? "karras" : "lbvh") + std::to_string(3 * p.bits_per_axis);
}

std::vector<lbvh_params> lbvh_variants() {
    std::vector<lbvh_params> list;
    for (const hierarchy_method h : {hierarchy_method::lecture, hierarchy_method::karras})
        for (const int bits : {10, 21}) {
            lbvh_params p;
            p.hierarchy = h, p.bits_per_axis = bits;
            list.push_back(p);
        }
    return list;
}

builder_inputs::builder_inputs(const triangle_mesh& mesh) {
    const ch01::triangle_set tris(mesh);
    boxes.reserve(tris.size()), centroids.reserve(tris.size());
    for (std::uint32_t i = 0; i < tris.size(); ++i) boxes.push_back(tris.bounds(i)), centroids.push_back(boxes.back().centroid());
}

std::vector<aabb> fit_boxes(const radix_tree& t, std::span<const aabb> leaf_boxes) {
    std::vector<aabb> inner(t.left.size());
    const auto box_of = [&](std::uint32_t ref) -> const aabb& {
        return is_leaf_ref(ref) ? leaf_boxes[ref & ~leaf_bit] : inner[ref];
    };
    bottom_up(t, [&](std::uint32_t i) { inner[i] = unite(box_of(t.left[i]), box_of(t.right[i])); });
    return inner;
}

ch04::bvh build_lbvh(std::span<const aabb> boxes, std::span<const vec3> centroids, const lbvh_params& params,
                     lbvh_report* report) {
    if (boxes.size() != centroids.size()) throw std::invalid_argument("build_lbvh: one centroid per box");
    if (params.bits_per_axis != 10 && params.bits_per_axis != 21)
        throw std::invalid_argument("build_lbvh: bits_per_axis must be 10 or 21");
    lbvh_params p = params;
    p.max_leaf = std::clamp(p.max_leaf, 1, 255);
    p.max_depth = std::clamp(p.max_depth, 33, ch04::bvh_max_depth);
    lbvh_report r;
    const timer total;
    timer phase;
    ch04::bvh out;
    out.stats.primitives = boxes.size();

    // 1. Codes (morton.hpp): the loose primitives set aside, one code per primitive in the tree.
    morton_codes codes = compute_morton_codes(boxes, centroids, p.bits_per_axis, p.use_pdep);
    r.codes_ms = phase.milliseconds(), phase.restart();
    // 2. Sort (key, id) pairs by code (radix_sort.hpp).
    radix_sort_params sort;
    sort.key_bits = 3 * p.bits_per_axis;
    radix_sort(codes.keys, codes.ids, sort);
    r.sort_ms = phase.milliseconds(), phase.restart();
    // 3. Hierarchy (radix_tree.hpp).
    radix_tree tree;
    if (p.hierarchy == hierarchy_method::karras)
        build_radix_tree_karras(codes.keys, tree);
    else
        build_radix_tree_lecture(codes.keys, tree);
    r.hierarchy_ms = phase.milliseconds(), phase.restart();
    // 4. Boxes: the primitives' boxes gathered in leaf order (so that the passes below read them in order,
    //    not scattered over the input), then the inner nodes' bottom up.
    std::vector<aabb> leaf_boxes(codes.ids.size());
    parallel_for_chunks(leaf_boxes.size(), 4096, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) leaf_boxes[k] = boxes[codes.ids[k]];
    });
    const std::vector<aabb> inner_boxes = fit_boxes(tree, leaf_boxes);
    r.boxes_ms = phase.milliseconds(), phase.restart();
    // 5. Collapse: the SAH's leaves, written depth first into the flat array.
    if (!codes.ids.empty()) {
        out.nodes.reserve(2 * codes.ids.size() - 1);
        collapser c{tree, leaf_boxes, inner_boxes, p, out, r, {}, {}, {}, {}, {}};
        c.price();
        const std::uint32_t root = codes.ids.size() == 1 ? leaf_bit : 0u;
        if (!c.write_all(root)) c.emit(root, 0);
        out.bounds = out.nodes[0].box();
    }
    out.prim_ids = std::move(codes.ids);
    out.loose = std::move(codes.loose);
    r.collapse_ms = phase.milliseconds();
    out.stats.build_ms = total.milliseconds();

    if (report) {
        for (std::size_t k = 1; k < codes.keys.size(); ++k) r.duplicate_codes += codes.keys[k] == codes.keys[k - 1];
        *report = r;
    }
    return out;
}

}  // namespace strahl::ch07
