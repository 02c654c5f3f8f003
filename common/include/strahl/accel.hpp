// The one interface of every acceleration structure in the course: build over a scene's triangles, then
// answer batches of closest-hit and any-hit queries. The race, the tests and strahl-trace all use it, so a
// structure registered once (chapters/16_race) appears everywhere.
//
// One virtual call per batch; the loop inside a batch is the structure's own, fully inlined code.
#pragma once
#include "strahl/ray.hpp"
#include "strahl/ray_frame.hpp"
#include "strahl/scene.hpp"
#include "strahl/stats.hpp"
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace strahl {

class accel {
public:
    virtual ~accel() = default;

    virtual std::string name() const = 0;

    // Builds over s.mesh: primitive id i is triangle i. (Spheres and planes are chapter 01's business.)
    virtual void build(const scene& s) = 0;

    // Closest hit with t in (tmin, tmax) per ray, under the rule of closer() (ray.hpp); a miss leaves
    // t = inf, prim = invalid_id.
    // const and thread-safe: the race calls it on chunks of one batch from several threads.
    virtual void intersect(std::span<const ray> rays, std::span<hit> hits) const = 0;

    // Any hit with t in (tmin, tmax) per ray, the interval of the closest-hit query: blocked[i] = 1 if there
    // is one, else 0.
    virtual void occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const = 0;

    // The same queries, counting box tests, primitive tests and nodes visited; nullopt where the structure
    // cannot count (Embree). Results must equal the uncounted queries'.
    virtual std::optional<counter_values> intersect_counted(std::span<const ray> rays, std::span<hit> hits) const {
        (void)rays, (void)hits;
        return std::nullopt;
    }
    virtual std::optional<counter_values> occluded_counted(std::span<const ray> rays,
                                                           std::span<std::uint8_t> blocked) const {
        (void)rays, (void)blocked;
        return std::nullopt;
    }

    // Bytes the built structure holds (nodes, index arrays, copies of geometry it made).
    virtual std::size_t memory_bytes() const = 0;

    // The SAH cost of the built tree (chapter 05's definition, normalised by the root's area) where defined.
    virtual std::optional<double> sah_cost() const { return std::nullopt; }

    // Batches handed to intersect()/occluded() from a split of a larger batch start at multiples of this
    // many rays (packet tracers that group rays by pixel tiles need whole tile rows).
    virtual std::size_t batch_alignment() const { return 1; }

    // True for the course's structures, which must reproduce brute force bit for bit; false for Embree,
    // whose own triangle test may differ on a handful of edge cases (the race counts them).
    virtual bool exact() const { return true; }
};

// Most structures answer one ray at a time. Deriving from per_ray_accel<Derived> supplies the four batch
// queries from Derived's two per-ray ones, templated on the counters (stats.hpp):
//   template <class Stats> hit closest(const ray& r, Stats& stats) const;
//   template <class Stats> bool any(const ray& r, Stats& stats) const;
// Each batch is one virtual call; the loop over its rays calls Derived's code directly (and inlines it).
// Base is accel, or an interface of a chapter's own that derives from accel.
// Every query goes through the structure's ray_frame (ray_frame.hpp): Derived's build() sets it to the box
// of everything it holds (set_frame), as brute force does, so that rays from far away are answered from
// near the scene by both alike.
template <class Derived, class Base = accel>
class per_ray_accel : public Base {
public:
    void intersect(std::span<const ray> rays, std::span<hit> hits) const override {
        not_counting stats;
        closest_batch(rays, hits, stats);
    }
    void occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const override {
        not_counting stats;
        any_batch(rays, blocked, stats);
    }
    std::optional<counter_values> intersect_counted(std::span<const ray> rays, std::span<hit> hits) const override {
        counting stats;
        closest_batch(rays, hits, stats);
        return stats.values();
    }
    std::optional<counter_values> occluded_counted(std::span<const ray> rays,
                                                   std::span<std::uint8_t> blocked) const override {
        counting stats;
        any_batch(rays, blocked, stats);
        return stats.values();
    }

    // The frame far origins are moved by; ray_frame() moves none (chapter 15 measures what that costs).
    const ray_frame& frame() const { return frame_; }
    void set_frame(const ray_frame& f) { frame_ = f; }

private:
    // A batch with no far origin (every batch of the course's scenes) goes straight to the loop; one with
    // any goes through the same loop on moved copies, t0 added back after. One copy of the walk either way.
    template <class Stats>
    void closest_batch(std::span<const ray> rays, std::span<hit> hits, Stats& stats) const {
        if (!frame_.moves_any(rays)) [[likely]]
            return closest_all(rays, hits, stats);
        std::vector<ray> moved(rays.size());
        std::vector<float> t0(rays.size());
        for (std::size_t i = 0; i < rays.size(); ++i) moved[i] = frame_.moved(rays[i], t0[i]);
        closest_all(moved, hits, stats);
        for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = ray_frame::moved_back(hits[i], t0[i]);
    }
    template <class Stats>
    void any_batch(std::span<const ray> rays, std::span<std::uint8_t> blocked, Stats& stats) const {
        if (!frame_.moves_any(rays)) [[likely]]
            return any_all(rays, blocked, stats);
        std::vector<ray> moved(rays.size());
        float t0;
        for (std::size_t i = 0; i < rays.size(); ++i) moved[i] = frame_.moved(rays[i], t0);
        any_all(moved, blocked, stats);
    }
    // The loops, out of line so that the inliner spends its budget on the walk inside them, as when they
    // were the whole of intersect() (the frame's check inlined beside them cost 27% on the bunny's primary
    // rays: the walk was no longer inlined into the loop).
    template <class Stats>
    [[gnu::noinline]] void closest_all(std::span<const ray> rays, std::span<hit> hits, Stats& stats) const {
        const Derived& self = static_cast<const Derived&>(*this);
        for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = self.closest(rays[i], stats);
    }
    template <class Stats>
    [[gnu::noinline]] void any_all(std::span<const ray> rays, std::span<std::uint8_t> blocked, Stats& stats) const {
        const Derived& self = static_cast<const Derived&>(*this);
        for (std::size_t i = 0; i < rays.size(); ++i) blocked[i] = self.any(rays[i], stats) ? 1 : 0;
    }

    ray_frame frame_;
};

}  // namespace strahl
