// Procedural scenes: always available, no file needed, deterministic for a given seed.
#pragma once
#include "strahl/scene.hpp"
#include <cstdint>
#include <string>
#include <vector>

namespace strahl {

// The Cornell box (0..1 cube, opening towards +z): floor, ceiling, back wall (white), left wall (red),
// right wall (green) as 10 triangles, in that order, two per wall. With spheres: a mirror sphere and a
// rough-mirror sphere standing on the floor. One point light below the ceiling; camera looking in.
scene cornell_box(bool with_spheres = true);

// The Utah teapot (Martin Newell, 1975) from its 32 bicubic Bezier patches, each patch tessellated into
// resolution x resolution quads = 2 * resolution^2 triangles; 32 * 2 * resolution^2 triangles in all.
// Order: patch by patch in the classic data's order, rows in v, columns in u, each quad's two triangles.
// Degenerate triangles at the lid and bottom poles are kept (they are part of the classic mesh).
triangle_mesh teapot_mesh(int resolution);

// The teapot on a ground plane with a light and camera (a diffuse teapot and plane).
scene teapot_scene(int resolution = 8);

// The teapot in a stadium (Haines): a small, finely tessellated teapot at the centre of a huge, coarsely
// tessellated stadium bowl: many triangles in a tiny part of space, the case that breaks uniform grids.
// The teapot's triangles come first, then the stadium's. The camera looks at the teapot.
scene teapot_in_stadium(int teapot_resolution = 8, int stadium_segments = 64);

// Unit sphere at the origin as a UV sphere of `stacks` x `slices` quads (poles as single triangles).
triangle_mesh tessellated_sphere(int stacks, int slices);

// count triangles with vertices uniform in the unit cube... of edge length about `size` each.
triangle_mesh random_soup(std::size_t count, std::uint64_t seed, float size = 0.05f);

// count triangles gathered in `clusters` tight Gaussian-like clumps inside the unit cube.
triangle_mesh clustered_soup(std::size_t count, std::uint64_t seed, int clusters = 8, float size = 0.01f);

// Wraps a mesh into a scene with one diffuse material, a framing camera and a light.
scene mesh_scene(std::string name, triangle_mesh mesh);

// Names accepted by builtin_scene(): cornell, teapot, teapot_stadium, sphere, soup, clustered_soup.
std::vector<std::string> builtin_scene_names();
scene builtin_scene(const std::string& name);  // throws std::invalid_argument for an unknown name

}  // namespace strahl
