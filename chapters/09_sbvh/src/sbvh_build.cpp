// BUILD-SBVH: chapter 05's top-down SAH build with spatial splits (sbvh.hpp).
//   M. Stich, H. Friedrich and A. Dietrich, "Spatial splits in bounding volume hierarchies", HPG 2009.
#include "strahl/ch09/sbvh.hpp"
#include "strahl/ch09/spatial_split.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace strahl::ch09 {

std::string to_string(const sbvh_params& p) {
    std::ostringstream s;
    s << "sbvh";
    if (p.alpha != sbvh_params{}.alpha) s << "-a" << p.alpha;
    if (p.budget != sbvh_params{}.budget) s << "-b" << p.budget;
    return s.str();
}

namespace {

constexpr float inf = std::numeric_limits<float>::infinity();

// The object split (STEP 1): bins [0, boundary) of `mapping` go left (binned), or the first `boundary`
// references in (centroid, triangle) order on `axis` (swept, small nodes).
struct object_split {
    int axis = -1;
    int boundary = 0;
    float cost = inf;
    bool swept = false;
    ch05::bin_mapping mapping;
    aabb left, right;
};

bool centroid_less(const reference& x, const reference& y, int a) {
    const float cx = x.box.min[a] + x.box.max[a], cy = y.box.min[a] + y.box.max[a];
    return cx < cy || (cx == cy && x.tri < y.tri);
}

struct builder {
    sbvh_params p;
    std::span<const triangle> tris;
    ch04::bvh& t;
    sbvh_report& report;
    float root_area = 0.0f;
    std::size_t budget_left = 0;
    std::vector<chopped_bin> chopped;
    std::vector<ch05::bin> bins;
    std::vector<float> right_area;

    object_split find_object_split(std::vector<reference>& refs, const aabb& cbox, float area) {
        object_split best;
        const std::size_t n = refs.size();
        const bool swept = n <= std::size_t(p.object_bins);
        for (int a = 0; a < 3; ++a) {
            if (!(cbox.max[a] > cbox.min[a])) continue;
            int k = 0;
            ch05::bin_mapping m;
            if (swept) {
                // Every boundary between sorted centroids: one reference per "bin".
                std::sort(refs.begin(), refs.end(), [a](const reference& x, const reference& y) { return centroid_less(x, y, a); });
                k = int(n);
                for (std::size_t i = 0; i < n; ++i) bins[i] = {refs[i].box, 1};
            } else {
                m = ch05::make_bin_mapping(cbox.min[a], cbox.max[a], p.object_bins);
                if (!std::isfinite(m.scale)) continue;
                k = m.k;
                std::fill(bins.begin(), bins.begin() + k, ch05::bin{});
                for (const reference& r : refs) {
                    ch05::bin& b = bins[std::size_t(ch05::bin_index(m, r.box.centroid()[a]))];
                    b.box.grow(r.box), ++b.count;
                }
            }
            const ch05::bin_split s = ch05::best_boundary(std::span(bins.data(), std::size_t(k)),
                                                          std::span(right_area.data(), std::size_t(k)), p.costs, area);
            if (s.cost < best.cost) {
                best = {a, s.index, s.cost, swept, m, {}, {}};
                for (int b = 0; b < k; ++b) (b < s.index ? best.left : best.right).grow(bins[std::size_t(b)].box);
            }
        }
        return best;
    }

    // STEP 5 for an object split (or the median, axis < 0 in s): the two sides, refs released.
    void partition_objects(std::vector<reference>& refs, const object_split& s, const aabb& cbox,
                           std::vector<reference>& left, std::vector<reference>& right) {
        std::size_t mid = 0;
        int a = s.axis;
        if (a >= 0 && s.swept) {
            std::sort(refs.begin(), refs.end(), [a](const reference& x, const reference& y) { return centroid_less(x, y, a); });
            mid = std::size_t(s.boundary);
        } else if (a >= 0) {
            mid = std::size_t(std::partition(refs.begin(), refs.end(), [&](const reference& r) {
                                  return ch05::bin_index(s.mapping, r.box.centroid()[a]) < s.boundary;
                              }) - refs.begin());
        }
        if (mid == 0 || mid >= refs.size()) {
            // The object median on the centroid box's longest axis; all centroids in one point: halved as they are.
            ++report.median_splits;
            a = cbox.largest_axis();
            mid = refs.size() / 2;
            if (cbox.max[a] > cbox.min[a])
                std::nth_element(refs.begin(), refs.begin() + std::ptrdiff_t(mid), refs.end(),
                                 [a](const reference& x, const reference& y) { return centroid_less(x, y, a); });
        } else {
            ++report.object_splits;
        }
        left.assign(refs.begin(), refs.begin() + std::ptrdiff_t(mid));
        right.assign(refs.begin() + std::ptrdiff_t(mid), refs.end());
    }

    std::uint32_t build(std::vector<reference>& refs, int depth) {
        const auto index = std::uint32_t(t.nodes.size());
        t.nodes.emplace_back();
        t.stats.depth = std::max(t.stats.depth, depth);
        aabb box, cbox;
        for (const reference& r : refs) box.grow(r.box), cbox.grow(r.box.centroid());
        for (int a = 0; a < 3; ++a) t.nodes[index].bmin[a] = box.min[a], t.nodes[index].bmax[a] = box.max[a];
        const std::size_t n = refs.size();
        const auto make_leaf = [&] {
            t.nodes[index].offset = std::uint32_t(t.prim_ids.size());
            t.nodes[index].count = std::uint16_t(n);
            for (const reference& r : refs) t.prim_ids.push_back(r.tri);
            ++t.stats.leaves;
            t.stats.max_leaf = std::max(t.stats.max_leaf, n);
            return index;
        };
        if (n == 1) return make_leaf();
        // STEP 1, object split; STEP 2, overlap; STEP 3, spatial split (all only above the depth limit).
        const float area = box.surface_area();
        object_split obj;
        spatial_split spatial;
        if (depth < ch04::spatial_depth_limit && area > 0.0f && std::isfinite(area)) {
            obj = find_object_split(refs, cbox, area);
            const aabb overlap{glm::max(obj.left.min, obj.right.min), glm::min(obj.left.max, obj.right.max)};
            const float lambda = obj.axis < 0 || overlap.is_empty() ? 0.0f : overlap.surface_area() / root_area;
            if (lambda > p.alpha && budget_left > 0) {
                ++report.spatial_tried;
                spatial = find_spatial_split(refs, tris, box, area, p.costs, chopped);
            }
        }
        // STEP 4, the cheaper split, or a leaf.
        const float best = std::min(obj.cost, spatial.cost);
        if (n <= std::size_t(p.max_leaf) && (!(best < inf) || ch05::leaf_cost(p.costs, n) <= best)) return make_leaf();
        // STEP 5, distribute.
        std::vector<reference> left, right;
        int axis = obj.axis;
        if (spatial.cost < obj.cost) {
            left.reserve(spatial.n_left), right.reserve(spatial.n_right);
            const std::size_t before = budget_left;
            const std::size_t unsplit = distribute(refs, tris, spatial, p.unsplit, budget_left, left, right);
            if (left.empty() || right.empty()) {
                budget_left = before;  // (nothing was split: a side is empty)
                left.clear(), right.clear();
            } else {
                ++report.spatial_splits, report.unsplit += unsplit, axis = spatial.axis;
            }
        }
        if (left.empty() || right.empty()) {
            partition_objects(refs, obj, cbox, left, right);
            axis = obj.axis >= 0 ? obj.axis : cbox.largest_axis();
        }
        std::vector<reference>().swap(refs);  // the parent's references are not needed below
        // STEP 6: left child next, the right child's index into offset.
        ++t.stats.inner;
        t.nodes[index].axis = std::uint8_t(axis);
        build(left, depth + 1);
        const std::uint32_t right_index = build(right, depth + 1);
        t.nodes[index].offset = right_index;
        return index;
    }
};

}  // namespace

ch04::bvh build_sbvh(const triangle_mesh& mesh, const sbvh_params& params, sbvh_report* report) {
    const timer clock;
    sbvh_params p = params;
    p.object_bins = std::clamp(p.object_bins, 2, 256);
    p.spatial_bins = std::clamp(p.spatial_bins, 2, 256);
    p.max_leaf = std::clamp(p.max_leaf, 1, 255);
    if (!(p.budget >= 1.0f)) p.budget = 1.0f;  // (NaN too)
    ch04::bvh t;
    sbvh_report rep;
    t.stats.primitives = mesh.triangle_count();
    // The root's references: one per triangle that fits in a tree; the others are loose.
    std::vector<triangle> tris(mesh.triangle_count());
    std::vector<reference> refs;
    refs.reserve(tris.size());
    aabb root;
    for (std::size_t i = 0; i < tris.size(); ++i) {
        const auto v = mesh.triangle(i);
        tris[i] = {v[0], v[1], v[2]};
        const aabb b = tris[i].bounds();
        if (!ch04::fits_in_tree(b, b.centroid())) {
            t.loose.push_back(std::uint32_t(i));
            continue;
        }
        refs.push_back({b, std::uint32_t(i)});
        root.grow(b);
    }
    rep.triangles = refs.size();
    if (!refs.empty()) {
        // The budget, and with it the memory: at most budget * N references and 2 per reference nodes.
        const double allowed = std::floor(double(p.budget) * double(refs.size()));
        rep.budget = std::size_t(std::min(allowed, double(std::numeric_limits<std::uint32_t>::max())));
        rep.budget = std::max(rep.budget, refs.size());
        t.prim_ids.reserve(rep.budget);
        t.nodes.reserve(2 * rep.budget - 1);
        builder b{p, tris, t, rep, root.surface_area(), 0, {}, {}, {}};
        b.budget_left = rep.budget - refs.size();
        b.chopped.resize(std::size_t(p.spatial_bins));
        b.bins.resize(std::size_t(std::max(p.object_bins, 256)));
        b.right_area.resize(b.bins.size());
        b.build(refs, 0);
        t.bounds = t.nodes[0].box();
    }
    rep.references = t.prim_ids.size();
    t.stats.build_ms = clock.milliseconds();
    if (report) *report = rep;
    return t;
}

}  // namespace strahl::ch09
