// The index form of a BVH, in and out: chapter 04's flat depth-first nodes into nodes with parent, left and
// right links (where a rotation or a reinsertion rewrites a few links), and the re-flattening afterwards.
//   M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, section 7.3 (the depth-first flattening);
//   A. Kensler, IEEE Symposium on Interactive Ray Tracing 2008, and J. Bittner, M. Hapala and V. Havran,
//   Computer Graphics Forum 2013, who both refine a pointer form.
// Steps: UNFLATTEN (links from the flat offsets, heights bottom up); FLATTEN (depth first, the child with the
// lower box centre on the split axis first, prim_ids regrouped in leaf order, stats recomputed).
#include "strahl/ch06/refine.hpp"
#include <stdexcept>

namespace strahl::ch06 {

namespace {

// FLATTEN one subtree at depth `depth`: appends its nodes depth first and its leaves' ids in order.
std::uint32_t flatten(const refine_tree& t, std::uint32_t n, int depth, ch04::bvh& out) {
    const refine_node& x = t.nodes[n];
    const auto index = std::uint32_t(out.nodes.size());
    ch04::bvh_node f{};
    for (int a = 0; a < 3; ++a) f.bmin[a] = x.box.min[a], f.bmax[a] = x.box.max[a];
    out.nodes.push_back(f);
    out.stats.depth = std::max(out.stats.depth, depth);
    if (x.is_leaf()) {
        out.nodes[index].offset = std::uint32_t(out.prim_ids.size());
        out.nodes[index].count = std::uint16_t(x.count);
        out.prim_ids.insert(out.prim_ids.end(), t.prim_ids.begin() + x.first, t.prim_ids.begin() + x.first + x.count);
        ++out.stats.leaves;
        out.stats.max_leaf = std::max<std::size_t>(out.stats.max_leaf, x.count);
        return index;
    }
    ++out.stats.inner;
    // The split axis: where the children's box centres lie farthest apart; the lower one goes first.
    const vec3 cl = t.nodes[x.left].box.centroid(), cr = t.nodes[x.right].box.centroid();
    const int axis = max_axis(glm::abs(cr - cl));
    const bool swap = cl[axis] > cr[axis];
    out.nodes[index].axis = std::uint8_t(axis);
    flatten(t, swap ? x.right : x.left, depth + 1, out);
    const std::uint32_t second = flatten(t, swap ? x.left : x.right, depth + 1, out);
    out.nodes[index].offset = second;
    return index;
}

}  // namespace

refine_tree to_refine_tree(const ch04::bvh& flat) {
    refine_tree t;
    t.prim_ids = flat.prim_ids;
    if (flat.nodes.empty()) return t;
    // UNFLATTEN: same indices; the left child of node i is i + 1, the right one its offset.
    t.nodes.resize(flat.nodes.size());
    for (std::size_t i = 0; i < flat.nodes.size(); ++i) {
        const ch04::bvh_node& f = flat.nodes[i];
        refine_node& x = t.nodes[i];
        x.box = f.box();
        if (f.is_leaf()) {
            x.first = f.offset;
            x.count = f.count;
        } else {
            x.left = std::uint32_t(i + 1);
            x.right = f.offset;
            t.nodes[x.left].parent = t.nodes[x.right].parent = std::uint32_t(i);
        }
    }
    // Heights bottom up: in depth-first order every child comes after its parent.
    for (std::size_t i = t.nodes.size(); i-- > 0;)
        if (!t.nodes[i].is_leaf())
            t.nodes[i].height = 1 + std::max(t.nodes[t.nodes[i].left].height, t.nodes[t.nodes[i].right].height);
    t.root = 0;
    return t;
}

ch04::bvh to_bvh(const refine_tree& t, const ch04::bvh& original) {
    ch04::bvh out;
    out.loose = original.loose;
    out.stats.primitives = original.stats.primitives;
    out.stats.build_ms = original.stats.build_ms;
    if (t.root == no_node) return out;
    out.nodes.reserve(t.nodes.size());
    out.prim_ids.reserve(t.prim_ids.size());
    flatten(t, t.root, 0, out);
    out.bounds = t.nodes[t.root].box;
    if (out.prim_ids.size() != t.prim_ids.size()) throw std::logic_error("to_bvh: a leaf was lost or doubled");
    return out;
}

const char* to_string(rotation r) {
    switch (r) {
        case rotation::left_right_left: return "L<->RL";
        case rotation::left_right_right: return "L<->RR";
        case rotation::right_left_left: return "R<->LL";
        case rotation::right_left_right: return "R<->LR";
        default: return "none";
    }
}
const char* to_string(refine_method m) { return m == refine_method::rotations ? "rotated" : "reinserted"; }
const char* to_string(start_tree s) { return s == start_tree::median ? "median" : "binned16"; }

}  // namespace strahl::ch06
