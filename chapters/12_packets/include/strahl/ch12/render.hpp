// Chapter 11's Whitted renderer with its primary and shadow rays traced in packets: per image tile, every
// primary ray in one batch (cut into 4x4 blocks, a packet each), then every shadow ray of its hits in one
// batch, then the shading of each pixel in chapter 01's order, its reflection rays traced one at a time as
// before. The image equals the single-ray renderer's bit for bit: the same rays, the same hits, the same
// arithmetic in the same order.
//   T. Whitted, "An improved illumination model for shaded display", CACM 23(6), 1980;
//   I. Wald, P. Slusallek, C. Benthin and M. Wagner, "Interactive rendering with coherent ray tracing",
//   Eurographics 2001 (shading after tracing a packet).
#pragma once
#include "strahl/accel.hpp"
#include "strahl/camera.hpp"
#include "strahl/ch01/render.hpp"
#include "strahl/ch11/step_accels.hpp"
#include <vector>

namespace strahl::ch12 {

// What chapter 11's whitted() asks of a tracer, over any accel of a triangle scene: the surface of a closest
// hit (the point, the unit normal from the triangle's edges turned towards the ray, the material) and
// whether a ray is blocked. One ray per call; the packet renderer calls surface_of on a batch's hits.
class accel_tracer {
public:
    accel_tracer(const accel& a, const scene& s);
    bool closest_surface(const ray& r, ch11::surface& s) const;
    bool occluded_ray(const ray& r) const;
    ch11::surface surface_of(const ray& r, const hit& h) const;

private:
    const accel* a_;
    const triangle_mesh* mesh_;
    std::vector<std::uint32_t> materials_;
};

// The scene's triangles and lights rendered with chapter 11's variant materials: single-ray (every ray
// through `single`, chapter 11's render_with) or with packets (primary and shadow rays through `packets`,
// reflection rays through `single`). The packet renderer wants `packets` made with image_width 0: it lays
// each tile's rays out in 4x4 blocks itself.
ch01::render_result render_single(const accel& single, const scene& s, const camera& cam,
                                  const ch01::render_settings& settings, int glossy);
ch01::render_result render_packets(const accel& packets, const accel& single, const scene& s, const camera& cam,
                                   const ch01::render_settings& settings, int glossy);

}  // namespace strahl::ch12
