// quantize(): a collapsed tree's float nodes as quantised nodes (quantized_node.hpp).
#include "strahl/ch13/quantized_node.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace strahl::ch13 {

namespace {

// The smallest origin and step the grid uses: with both at least 2^-100 in magnitude (or the origin 0), every
// decoded plane is 0 or a normal float, so flushing subnormals to zero (as Embree's callers set the
// processor) cannot change one.
constexpr float min_grid = 0x1p-100f;

// One axis of a node's grid: origin at or below lo, a power-of-two step with 255 steps reaching hi.
struct grid {
    float origin, step;
    grid(float lo, float hi) {
        origin = lo;
        if (std::fabs(origin) < min_grid) origin = origin < 0.0f ? -min_grid : 0.0f;
        const double extent = double(hi) - double(origin);  // exact in double
        int e = -100;
        if (extent > 0.0) e = std::max(e, std::ilogb(extent / 255.0));
        while (255.0 * std::ldexp(1.0, e) < extent) ++e;
        step = std::ldexp(1.0f, std::min(e, 127));
    }
    float decode(int q) const { return float(q) * step + origin; }
    // The largest q whose plane lies at or below x (0's plane, the origin, always does).
    std::uint8_t down(float x) const {
        int q = int(std::clamp(std::floor((double(x) - origin) / step), 0.0, 255.0));
        while (q > 0 && decode(q) > x) --q;
        while (q < 255 && decode(q + 1) <= x) ++q;
        return std::uint8_t(q);
    }
    // The smallest q whose plane lies at or above x.
    std::uint8_t up(float x) const {
        int q = int(std::clamp(std::ceil((double(x) - origin) / step), 0.0, 255.0));
        while (q < 255 && decode(q) < x) ++q;
        while (q > 0 && decode(q - 1) >= x) --q;
        return std::uint8_t(q);
    }
};

}  // namespace

template <int N, int M>
wide_bvh<N, M, qnode<N>> quantize(const wide_bvh<N, M>& tree) {
    wide_bvh<N, M, qnode<N>> out;
    out.root_ref = tree.root_ref;
    out.blocks = tree.blocks;
    out.loose = tree.loose;
    out.stats = tree.stats;
    out.nodes.resize(tree.nodes.size());
    aabb bounds = tree.bounds;
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        const wide_node<N>& n = tree.nodes[i];
        qnode<N>& q = out.nodes[i];
        aabb box;
        for (int k = 0; k < N; ++k)
            if (n.used(k)) box.grow(n.box(k));
        for (int k = 0; k < N; ++k) q.child[k] = n.child[k], q.order[k] = n.order[k];
        for (int a = 0; a < 3; ++a) {
            const grid g = box.is_empty() ? grid(0.0f, 0.0f) : grid(box.min[a], box.max[a]);
            q.origin[a] = g.origin, q.step[a] = g.step;
            for (int k = 0; k < N; ++k) {
                if (!n.used(k)) {
                    q.q[a][k] = 255, q.q[3 + a][k] = 0;
                    continue;
                }
                q.q[a][k] = g.down(n.lo[a][k]);
                q.q[3 + a][k] = g.up(n.hi[a][k]);
            }
        }
        for (int k = 0; k < N; ++k) {
            if (!n.used(k)) continue;
            q.used_bits |= 1u << k;
            const aabb d = q.box(k), b = n.box(k);
            for (int a = 0; a < 3; ++a)
                if (!(d.min[a] <= b.min[a] && d.max[a] >= b.max[a]))
                    throw std::logic_error("quantize: a decoded box does not hold its child's box");
            bounds.grow(d);
        }
    }
    out.set_bounds(bounds);
    return out;
}

template wide_bvh<4, 4, qnode<4>> quantize<4, 4>(const wide_bvh<4, 4>&);
template wide_bvh<8, 4, qnode<8>> quantize<8, 4>(const wide_bvh<8, 4>&);
template wide_bvh<8, 8, qnode<8>> quantize<8, 8>(const wide_bvh<8, 8>&);
template wide_bvh<16, 4, qnode<16>> quantize<16, 4>(const wide_bvh<16, 4>&);
template wide_bvh<16, 8, qnode<16>> quantize<16, 8>(const wide_bvh<16, 8>&);

}  // namespace strahl::ch13
