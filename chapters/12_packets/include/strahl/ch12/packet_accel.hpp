// The packet tracer behind the accel interface (accel.hpp), as a class template over the walk, K and V. Per
// packet: each ray checked as tree_query.hpp checks it (an empty interval is a miss; loose primitives
// first); a ray that no packet can take (not placeable, or a direction the fast slab test refuses) is traced
// alone, by chapter 05's fast walk on the binary tree or chapter 13's walk on the wide one, which give the
// same answers; the others fill the lanes, and the packet goes down the tree. The walks on the wide tree
// keep only the wide tree (the binary one is dropped after the collapse, as chapter 13's accel does).
//
// Instantiated where the box test it inlines is defined: chapter 12's walks at the end of packet_tests.cpp
// (exercises 12.1 to 12.3, packet_accel_impl.hpp); chapter 14's hybrid, a Policy that changes the wide
// walk's box test and adds the switch to single rays, at the end of its own exercise file.
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch05/fast_traverse.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch12/accel.hpp"
#include "strahl/ch12/binary_walks.hpp"
#include "strahl/ch12/frustum_walk.hpp"
#include "strahl/ch12/partition_walk.hpp"
#include "strahl/ch12/wide_packet_walk.hpp"
#include "strahl/ch13/wide_bvh.hpp"
#include "strahl/ch13/child_order.hpp"
#include "strahl/ch13/wide_queries.hpp"
#include "strahl/tree_query.hpp"
#include <memory>

namespace strahl::ch12 {

// counting, plus the active lanes of every node visit (binary_walks.hpp's count_lanes).
template <int K>
struct lane_counting : counting {
    std::uint64_t visits[K + 1] = {};
    std::uint64_t lane_sum = 0, node_visits = 0, packets = 0;
    // Chapter 14: per lane of the packet being traced, node_visits when its ray left the packet (a policy's
    // switch to single rays), none_left where it has not.
    static constexpr std::uint64_t none_left = ~std::uint64_t(0);
    std::uint64_t left_at[K];
    void lanes(int active, int) { ++visits[active], lane_sum += std::uint64_t(active), ++node_visits; }
    void left(int lane) {
        if (left_at[lane] == none_left) left_at[lane] = node_visits;
    }
};

// Chapter 12's wide walk: its own box test (exercise 12.1), every ray in the packet to the end.
struct packets_only {
    static constexpr bool departures = false;  // per_ray: the packet's mean lane utilisation
    template <bool Any, bool Coherent, int K, int N, int M, class Stats>
    packet_hooks<Coherent> hooks(const ch13::wide_bvh<N, M>&, ray_packet<K, 1>&, Stats&) const {
        return {};
    }
};

// A triangle of a binary leaf, in prim_ids order: what the lane test reads (edges as exercise 01.3
// computes them), 40 bytes.
struct leaf_triangle {
    float v0[3], e1[3], e2[3];
    std::uint32_t id;
};

// Policy: what the wide walk tests boxes with and whether rays leave the packet (packets_only, or chapter
// 14's hybrid); the binary-tree walks and the frustum walk ignore it.
template <walk_kind W, int K, int V, class Policy = packets_only>
class packet_accel final : public packet_accel_base {
    static_assert(W == walk_kind::masked || W == walk_kind::wide ? V == 1 : true);
    static constexpr bool wide_tree = W == walk_kind::wide || W == walk_kind::frustum;
    // The wide tree's leaves: blocks of this many triangles (the packet tests them one by one; the block size
    // sets how many the optimal collapse may gather into a leaf).
    static constexpr int wide_block = 8;
    // Walks that test whole vectors of the packet record closest hits K lanes at a time
    // (packet_record_lanes); the partition walk's gathered lanes one at a time (packet_record).
    static constexpr bool lanes_in_place = W != walk_kind::partition;

public:
    packet_accel(std::string name, const packet_config& c, Policy policy = {})
        : name_(std::move(name)), config_(c), policy_(policy) {}

    std::string name() const override { return name_; }
    // Exact unless the policy drops the slack below tmin (chapter 14's strict variant).
    bool exact() const override {
        if constexpr (requires { policy_.strict; }) return !policy_.strict;
        return true;
    }
    const packet_config& config() const override { return config_; }
    std::size_t batch_alignment() const override {
        return config_.image_width > 0 ? std::size_t(config_.tile_h) * std::size_t(config_.image_width) : 1;
    }

    void build(const scene& s) override {
        set_.reset(), lanes_.reset();
        frame_ = ray_frame(s.mesh.bounds());
        if (config_.builder) {
            binary_ = config_.builder(s.mesh);
        } else {
            std::vector<aabb> boxes(s.mesh.triangle_count());
            std::vector<vec3> centroids(boxes.size());
            for (std::size_t i = 0; i < boxes.size(); ++i) {
                const auto t = s.mesh.triangle(i);
                boxes[i] = aabb{}.grow(t[0]).grow(t[1]).grow(t[2]), centroids[i] = boxes[i].centroid();
            }
            ch05::sah_build_params params;
            params.method = ch05::sah_method::binned, params.bins = 16;
            binary_ = ch05::build_sah_bvh_fast(boxes, centroids, params);
        }
        tris_.clear();
        if constexpr (wide_tree) {
            ch13::collapse_config cc;
            cc.method = ch13::collapse_method::optimal;
            wide_ = ch13::collapse<8, wide_block>(binary_, s.mesh, cc);
            binary_ = {};  // the wide tree and its blocks are all the wide walks read
            // Chapter 14's lone rays read the nodes' any-hit order (the packet walks do not).
            if constexpr (requires { policy_.order; }) ch13::order_children(wide_, policy_.order);
            if constexpr (requires { policy_.octant; })
                if (policy_.octant) ch13::order_by_octant(wide_);
            box_ = tree_frame(wide_.bounds);
            static const std::vector<ch13::vertex_block<wide_block>> no_corners;
            lanes_ = std::make_unique<lane_set>(wide_, no_corners, s.mesh);
        } else {
            box_ = tree_frame(binary_.bounds);
            set_ = std::make_unique<ch01::triangle_set>(s.mesh);
            tris_.resize(binary_.prim_ids.size());
            for (std::size_t k = 0; k < tris_.size(); ++k) {
                const auto v = s.mesh.triangle(binary_.prim_ids[k]);
                const vec3 e1 = v[1] - v[0], e2 = v[2] - v[0];  // as exercise 01.3 computes them
                for (int a = 0; a < 3; ++a) tris_[k].v0[a] = v[0][a], tris_[k].e1[a] = e1[a], tris_[k].e2[a] = e2[a];
                tris_[k].id = binary_.prim_ids[k];
            }
        }
    }
    std::optional<double> sah_cost() const override {
        if (!built()) return std::nullopt;
        if constexpr (wide_tree) return wide_.stats.sah;
        else return ch04::sah_tree_cost(binary_, 1.0f, 1.0f);
    }
    // Everything it keeps: the wide tree and its blocks (with the few loose triangles), or the binary tree,
    // its leaves' triangles and the triangle set that single rays and loose primitives use.
    std::size_t memory_bytes() const override {
        if constexpr (wide_tree) return wide_.memory_bytes() + (lanes_ ? lanes_->memory_bytes() : 0);
        else return binary_.memory_bytes() + binary_.loose.size() * 4 + tris_.size() * sizeof(leaf_triangle) +
                    (set_ ? set_->memory_bytes() : 0);
    }

    void intersect(std::span<const ray> rays, std::span<hit> hits) const override {
        not_counting s;
        run<false>(rays, hits.data(), nullptr, s, nullptr);
    }
    void occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const override {
        not_counting s;
        run<true>(rays, nullptr, blocked.data(), s, nullptr);
    }
    std::optional<counter_values> intersect_counted(std::span<const ray> rays, std::span<hit> hits) const override {
        return closest_lanes(rays, hits, nullptr).counts;
    }
    std::optional<counter_values> occluded_counted(std::span<const ray> rays, std::span<std::uint8_t> blocked) const override {
        return any_lanes(rays, blocked, nullptr).counts;
    }
    lane_stats closest_lanes(std::span<const ray> rays, std::span<hit> hits, std::vector<float>* per_ray) const override {
        lane_counting<K> s;
        run<false>(rays, hits.data(), nullptr, s, per_ray);
        return stats_of(s);
    }
    lane_stats any_lanes(std::span<const ray> rays, std::span<std::uint8_t> blocked, std::vector<float>* per_ray) const override {
        lane_counting<K> s;
        run<true>(rays, nullptr, blocked.data(), s, per_ray);
        return stats_of(s);
    }

private:
    lane_stats stats_of(const lane_counting<K>& s) const {
        lane_stats l;
        l.counts = s.values();
        l.visits.assign(s.visits, s.visits + K + 1);
        l.packets = s.packets;
        return l;
    }

    // Far origins moved to the scene first (ray_frame.hpp), as per_ray_accel does for every structure.
    template <bool Any, class Stats>
    void run(std::span<const ray> rays, hit* hits, std::uint8_t* blocked, Stats& stats, std::vector<float>* per_ray) const {
        if (per_ray) per_ray->assign(rays.size(), -1.0f);
        if (!built()) {
            for (std::size_t i = 0; i < rays.size(); ++i) Any ? void(blocked[i] = 0) : void(hits[i] = hit{});
            return;
        }
        if (!frame_.moves_any(rays)) [[likely]]
            return trace<Any>(rays, hits, blocked, stats, per_ray);
        std::vector<ray> moved(rays.size());
        std::vector<float> t0(rays.size());
        for (std::size_t i = 0; i < rays.size(); ++i) moved[i] = frame_.moved(rays[i], t0[i]);
        trace<Any>(moved, hits, blocked, stats, per_ray);
        if constexpr (!Any)
            for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = ray_frame::moved_back(hits[i], t0[i]);
    }

    template <bool Any, class Stats>
    void trace(std::span<const ray> rays, hit* hits, std::uint8_t* blocked, Stats& stats, std::vector<float>* per_ray) const {
        const auto alone = [&](std::uint32_t i) {
            if constexpr (Any) blocked[i] = single_any(rays[i], stats) ? 1 : 0;
            else hits[i] = single_closest(rays[i], stats);
        };
        if (!(wide_tree ? wide_.loose.empty() : binary_.loose.empty())) {
            // Every ray of a scene with loose primitives (rare: non-finite triangles) goes alone.
            for (std::uint32_t i = 0; i < rays.size(); ++i) alone(i);
            return;
        }
        auto p = std::make_unique<ray_packet<K, V>>();
        for_each_packet(rays.size(), config_, [&](const std::uint32_t* ids, int count) {
            p->set_rays(rays.data(), ids, count);
            // The lanes' slab terms, K at a time. Alone: empty intervals, rays no tree can place, and
            // directions the fast test refuses.
            unsigned refused[V];
            p->set_terms(box_, refused);
            if constexpr (requires { policy_.strict; })
                if (policy_.strict) p->drop_lower_slack();
            for (int v = 0; v < V; ++v)
                for (unsigned b = refused[v]; b != 0; b &= b - 1) {
                    const int k = v * K + std::countr_zero(b);
                    alone(p->ray_index[k]);
                    p->active[v] &= ~(1u << (k % K));
                }
            if (p->empty()) return;
            for (int v = 0; v < V; ++v) stats.ray(std::uint64_t(std::popcount(p->active[v])));
            p->finish(box_);
            unsigned held[V];
            for (int v = 0; v < V; ++v) held[v] = p->active[v];
            std::uint64_t before = 0, visits_before = 0;
            if constexpr (requires { stats.lane_sum; }) before = stats.lane_sum, visits_before = stats.node_visits;
            if constexpr (requires { stats.packets; }) ++stats.packets;
            if constexpr (requires { stats.left_at; })
                for (int k = 0; k < K; ++k) stats.left_at[k] = stats.none_left;
            if (p->coherent) walk<Any, true>(*p, stats);
            else walk<Any, false>(*p, stats);
            float used = 0.0f;  // (a packet that misses the root visits no node)
            if constexpr (requires { stats.lane_sum; })
                if (stats.node_visits > visits_before)
                    used = float(double(stats.lane_sum - before) / double(stats.node_visits - visits_before) / K);
            for (int k = 0; k < K * V; ++k) {
                if (!((held[k / K] >> (k % K)) & 1u)) continue;
                const std::uint32_t i = p->ray_index[k];
                if constexpr (Any) blocked[i] = p->best(k).found() ? 1 : 0;
                else hits[i] = p->best(k);
                if (!per_ray) continue;
                if constexpr (!Policy::departures || !requires { stats.left_at; }) {
                    (*per_ray)[i] = used;
                } else {
                    // Chapter 14: the share of the packet's node visits made before the ray left it, below 1
                    // for every ray that left (also after the packet's last visit); 1: it never left.
                    const std::uint64_t at = stats.left_at[k % K], all = stats.node_visits - visits_before;
                    (*per_ray)[i] = at == stats.none_left ? 1.0f
                                    : all > 0 ? std::min(float(double(at - visits_before) / double(all)),
                                                         std::nextafter(1.0f, 0.0f))
                                              : 0.0f;
                }
            }
        });
    }

    // The leaf test on a packet's lanes: closest hit records (chapter 01's rule, per lane); any hit marks
    // the lane answered and takes it out of the packet.
    template <bool Any, class Stats>
    STRAHL_ALWAYS_INLINE bool test_triangle(ray_packet<K, V>& p, const lane_rays<K>& r, unsigned& lanes, auto at,
                                            const float* v0, const float* e1, const float* e2, std::uint32_t id,
                                              Stats& stats) const {
        stats.prim_test(std::popcount(lanes));
        simd::vfloat<K> t, u, w;
        const unsigned b = packet_triangle(r, v0, e1, e2, t, u, w) & lanes;
        if (b == 0) return false;
        if constexpr (Any) {
            for (unsigned x = b; x != 0; x &= x - 1) {
                const int i = at(std::countr_zero(x));
                p.active[i / K] &= ~(1u << (i % K));
                p.best_prim[i] = std::int32_t(id);
            }
            lanes &= ~b;
        } else if constexpr (lanes_in_place) {
            packet_record_lanes(p, at(0) / K, simd::from_bits<K>(b), id, t, u, w);
        } else {
            packet_record(p, b, at, id, t, u, w);
        }
        return true;
    }

    // The triangles of a wide leaf (blocks of 4) against the lanes of one vector; whether any lane hit.
    template <bool Any, class Stats>
    STRAHL_ALWAYS_INLINE bool wide_leaf(ray_packet<K, V>& p, const lane_rays<K>& r, unsigned lanes, auto at,
                                        std::uint32_t ref, Stats& stats) const {
        bool any = false;
        const ch13::triangle_block<wide_block>* b = &wide_.blocks[ch13::leaf_first(ref)];
        for (std::uint32_t k = ch13::leaf_blocks(ref); k-- > 0 && lanes != 0; ++b)
            for (int i = 0; i < wide_block && lanes != 0; ++i) {
                // A lane that repeats the one before: the padding past the leaf's end (which repeats its last
                // triangle), or a triangle an SBVH's leaves name twice, side by side once collapsed: the same
                // answer again, skipped (not the end of the leaf: stopping there lost hits).
                if (i > 0 && b->id[i] == b->id[i - 1]) continue;
                const float v0[3] = {b->v0[0][i], b->v0[1][i], b->v0[2][i]};
                const float e1[3] = {b->e1[0][i], b->e1[1][i], b->e1[2][i]};
                const float e2[3] = {b->e2[0][i], b->e2[1][i], b->e2[2][i]};
                any |= test_triangle<Any>(p, r, lanes, at, v0, e1, e2, b->id[i], stats);
            }
        return any;
    }

    template <bool Any, bool Coherent, class Stats>
    void walk(ray_packet<K, V>& p, Stats& stats) const {
        if constexpr (W == walk_kind::frustum && Coherent) {
            const auto leaf = [&](const lane_rays<K>& r, unsigned lanes, auto at, std::uint32_t ref, const float* bmin,
                                  const float* bmax) {
                // The vector against the leaf's box first: only its lanes that enter test the triangles.
                simd::vfloat<K> t;
                stats.box_test(std::popcount(lanes));
                const unsigned in = simd::movemask(packet_box<true>(r, bmin, bmax, p.octant, t)) & lanes;
                count_lanes(stats, std::popcount(in), K);
                if (in != 0 && wide_leaf<Any>(p, r, in, at, ref, stats) && !Any) p.update_t1_hi();
            };
            frustum_walk<!Any>(wide_, p, stats, leaf);
        } else if constexpr (wide_tree) {
            static_assert(W == walk_kind::wide || V == 1, "mixed octants in large packets: not built");
            const auto leaf = [&](const lane_rays<K>& r, unsigned lanes, auto at, std::uint32_t ref) {
                wide_leaf<Any>(p, r, lanes, at, ref, stats);
            };
            wide_packet_walk<!Any, Coherent>(wide_, p, stats, leaf,
                                             policy_.template hooks<Any, Coherent>(wide_, p, stats));
        } else {
            const auto leaf = [&](const lane_rays<K>& r, unsigned lanes, auto at, std::uint32_t first, std::uint32_t count) {
                for (std::uint32_t k = 0; k < count && lanes != 0; ++k) {
                    const leaf_triangle& t = tris_[first + k];
                    test_triangle<Any>(p, r, lanes, at, t.v0, t.e1, t.e2, t.id, stats);
                }
                if constexpr (!Any && V > 1) p.update_t1_hi();
            };
            if constexpr (W == walk_kind::masked) masked_walk<Coherent>(binary_, p, stats, leaf);
            else if constexpr (W == walk_kind::ranged) ranged_walk<Coherent>(binary_, p, stats, leaf);
            else partition_walk<Coherent>(binary_, p, stats, leaf);
        }
    }

    // A ray traced alone: chapter 05's fast walk over the same binary tree, or chapter 13's walk over the
    // same wide tree on its robust slab test (no exercise of chapter 13 in it); their answers are exact. Out
    // of line: these are the rare rays; inlined into trace() they slowed the packets themselves (the
    // hybrid's diffuse rays on the bunny 4.94 against 6.06 Mrays/s out of line, race, three processes).
    static auto block_test() {
        return [](const ch13::triangle_block<wide_block>& b, const ch13::ray_lanes<wide_block>& lanes, float tmin,
                  float tmax, simd::vfloat<wide_block>& t, simd::vfloat<wide_block>& u, simd::vfloat<wide_block>& v) {
            return ch13::intersect_block(b, lanes, tmin, tmax, t, u, v);
        };
    }
    template <class Stats>
    [[gnu::noinline]] hit single_closest(const ray& q, Stats& stats) const {
        if constexpr (wide_tree)
            return ch13::wide_closest<ch13::ray_lanes<wide_block>>(wide_, *lanes_, q, stats, block_test(), lone_walk(stats));
        else return tree_closest(*set_, binary_.loose, q, stats, lone_walk(stats));
    }
    template <class Stats>
    [[gnu::noinline]] bool single_any(const ray& q, Stats& stats) const {
        if constexpr (wide_tree)
            return ch13::wide_any<ch13::ray_lanes<wide_block>>(wide_, *lanes_, q, stats, block_test(), lone_walk(stats));
        else return tree_any(*set_, binary_.loose, q, stats, lone_walk(stats));
    }
    // The lone ray's walk, walk(r, leaf): leaf(ref) per wide leaf, or leaf(ids, count) per binary leaf.
    template <class Stats>
    auto lone_walk(Stats& stats) const {
        return [this, &stats](ray& r, auto&& leaf) {
            if constexpr (wide_tree) {
                ch13::robust_walk(wide_, r, stats, leaf);
            } else {
                ch05::fast_traverse(binary_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
                    return leaf(binary_.prim_ids.data() + first, count);
                });
            }
        };
    }
    bool built() const { return wide_tree ? lanes_ != nullptr : set_ != nullptr; }

    std::string name_;
    packet_config config_;
    Policy policy_;
    using lane_set = ch13::block_lane_set<8, wide_block, false>;
    std::unique_ptr<ch01::triangle_set> set_;  // the binary walks' triangles for single rays
    std::unique_ptr<lane_set> lanes_;          // the wide walks': the leaves' blocks, and the loose triangles
    ray_frame frame_;
    ch04::bvh binary_;
    tree_frame box_;
    std::vector<leaf_triangle> tris_;
    ch13::wide_bvh<8, wide_block> wide_;
};

}  // namespace strahl::ch12
