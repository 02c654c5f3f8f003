// Far origins moved to the scene ("origin rebasing", as renderers that draw planets or cities relative to
// the camera do). A triangle test's rounding grows with the distance from the ray's origin to the triangle:
// Moeller-Trumbore forms s = org - v0 and multiplies it into u, v and t, so each carries an absolute error of
// a few 2^-24 |s|. Seen from 10^6, a teapot triangle 0.05 across then accepts rays that pass a triangle's
// width beside it, and accepts them differently from its neighbours: brute force finds such a hit, while a
// tree's box test culls a box that the ray really misses, and the two disagree (chapter 15's far.csv).
//
// The rule, applied identically by brute force and by every structure (per_ray_accel; the race's chapter 01
// tracer; the tests' own brute-force loops; chapter 01's renderer keeps its rays as they are):
// a query whose origin lies more than 16 diagonals from the centre of the scene's box is answered along the
// same line from a point a little more than one diagonal before the scene,
//     org' = org + t0 dir,   interval (tmin - t0, tmax - t0),   t = t' + t0 for the hit,
// so |s| is at most a few diagonals wherever the ray can meet a triangle. Rounding org' moves the line by
// about 2^-24 |org|, once, for every triangle alike: brute force and the structures answer the same moved
// ray, and far away they answer it as accurately as near the scene. Origins within 16 diagonals (every
// camera and secondary ray of the course's scenes) are left exactly as they are.
#pragma once
#include "strahl/aabb.hpp"
#include "strahl/ray.hpp"
#include "strahl/scene.hpp"
#include <cmath>
#include <span>

namespace strahl {

class ray_frame {
public:
    // Moves nothing (the default, and for a box that is empty or not finite, e.g. a scene with planes).
    ray_frame() = default;
    explicit ray_frame(const aabb& box) {
        const vec3 e = box.max - box.min;
        const float diagonal = glm::length(e);
        if (box.is_empty() || !std::isfinite(diagonal) || !std::isfinite(glm::length(box.min)) ||
            !std::isfinite(glm::length(box.max)))
            return;
        center_ = box.centroid();
        reach_ = diagonal;
        far2_ = (16.0f * diagonal) * (16.0f * diagonal);
        center_length_ = glm::length(center_);
    }
    // The box of everything s holds: its triangles and spheres (scene::bounds), unbounded where it has planes.
    static ray_frame of_scene(const scene& s) { return s.planes.empty() ? ray_frame(s.bounds()) : ray_frame(); }

    bool active() const { return far2_ < inf; }

    // Whether r's origin is far enough to be moved (never for NaN or Inf origins).
    bool moves(const ray& r) const {
        const vec3 o = r.org - center_;
        return glm::dot(o, o) > far2_;
    }

    // Whether any ray of a batch moves (one pass, no branch per ray).
    bool moves_any(std::span<const ray> rays) const {
        bool any = false;
        for (const ray& r : rays) any |= moves(r);
        return any;
    }

    // The moved ray and its shift t0 (0 and r itself where nothing moves).
    ray moved(const ray& r, float& t0) const {
        t0 = 0.0f;
        if (!moves(r)) return r;
        const float len2 = glm::dot(r.dir, r.dir);
        if (!(len2 > 1e-30f && len2 < inf)) return r;  // a vanishing or unbounded direction: left to the structure
        const float len = std::sqrt(len2);
        // One diagonal before the centre's projection, plus 16 times the rounding of t0 and org + t0 dir
        // (a few 2^-24 of the distances involved), so the moved origin never passes anything the ray can hit.
        const float back = (reach_ + 0x1p-20f * (glm::length(r.org) + center_length_)) / len;
        const float shift = glm::dot(center_ - r.org, r.dir) / len2 - back;
        if (!std::isfinite(shift)) return r;
        t0 = shift;
        return ray{r.org + shift * r.dir, r.dir, r.tmin - shift, r.tmax - shift};
    }

    // The hit of the moved query back in r's own t (a miss stays a miss).
    static hit moved_back(hit h, float t0) {
        if (t0 != 0.0f && h.found()) h.t += t0;
        return h;
    }

    // closest(r) and any(r) answered through the frame, one ray at a time (brute-force loops).
    template <class Closest>
    hit closest(const ray& r, Closest&& closest) const {
        float t0 = 0.0f;
        const hit h = closest(moves(r) ? moved(r, t0) : r);  // t0 is set before it is read below
        return moved_back(h, t0);
    }
    template <class Any>
    bool any(const ray& r, Any&& any) const {
        float t0 = 0.0f;
        return any(moves(r) ? moved(r, t0) : r);
    }

private:
    vec3 center_{0.0f};
    float reach_ = 0.0f, center_length_ = 0.0f;
    float far2_ = inf;  // squared distance beyond which an origin is moved
};

}  // namespace strahl
