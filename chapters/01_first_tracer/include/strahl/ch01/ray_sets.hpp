// The rays everyone shares (chapter 01 makes them; the race, strahl-trace and the chapters' programs use them). Generated identically for every structure (and written to files, ray_io.hpp),
// so the race compares like with like:
//   primary: the scene's camera, one ray per pixel centre, scanline order, row 0 at the top;
//   diffuse: one per primary hit, in pixel order, leaving the hit point (computed from the barycentrics)
//            off the surface along the geometric normal turned towards the incoming ray, its direction
//            cosine-distributed around that normal from one PCG32 stream seeded with `seed`;
//   shadow:  one per primary hit, in pixel order, towards the scene's first point light, tmax just short
//            of the light (an any-hit query).
// The hits they start from come from an exact structure (brute force, or anything equal to it).
#pragma once
#include "strahl/accel.hpp"
#include <cstdint>
#include <string>
#include <vector>

namespace strahl::ch01 {

enum class ray_kind { primary, diffuse, shadow };
ray_kind parse_ray_kind(const std::string& name);  // "primary" | "diffuse" | "shadow"; else invalid_argument
std::string to_string(ray_kind k);
inline bool is_any_hit(ray_kind k) { return k == ray_kind::shadow; }

std::vector<ray> primary_rays(const scene& s, int width, int height);

// Throws std::invalid_argument when the scene has no point light.
std::vector<ray> secondary_rays(ray_kind kind, const scene& s, std::span<const ray> primary,
                                std::span<const hit> primary_hits, std::uint64_t seed = 1);

// Traces rays through an accel on `threads` threads (<= 1: on this thread), in chunks of about 1024
// consecutive rays aligned to a.batch_alignment() (smaller ones for a small set, so that the threads share
// it evenly); an exact structure's results are the same whatever the thread count.
void trace_closest(const accel& a, std::span<const ray> rays, std::span<hit> hits, int threads = 1);
// The chunk the two above hand each thread for n rays, a batch alignment and a thread count > 1.
std::size_t thread_chunk(std::size_t n, std::size_t align, int threads);
void trace_any(const accel& a, std::span<const ray> rays, std::span<std::uint8_t> blocked, int threads = 1);

// Convenience: one ray set of a kind for a scene and image size, primary hits found with `exact`.
std::vector<ray> make_rays(ray_kind kind, const scene& s, int width, int height, std::uint64_t seed,
                           const accel& exact, int threads = 1);

// The two ray sets a chapter program times every structure on, with the hits of `exact` as the reference
// each structure's hits must equal: primary rays for a width x height image and the diffuse rays (seed 1)
// from their hits.
struct checked_rays {
    std::vector<ray> primary, diffuse;
    std::vector<hit> primary_hits, diffuse_hits;
};
checked_rays make_checked_rays(const scene& s, int width, int height, const accel& exact);

// Both sets through `a` on this thread: Mrays/s from the median of `repeats` timed runs after a warm-up,
// and how many of a's hits differ from the reference's (0 for an exact structure).
struct checked_speed {
    double primary_mrays = 0, diffuse_mrays = 0;
    std::size_t differing = 0;
};
checked_speed time_checked(const accel& a, const checked_rays& rays, int repeats);

}  // namespace strahl::ch01
