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
// Walls face into the box. Materials: 0 white, 1 red, 2 green (diffuse), 3 mirror, 4 rough mirror
// (roughness 0.2). Light at (0.5, 0.95, 0.5); camera at (0.5, 0.5, 2.6), vfov 40. Name "cornell".
scene cornell_box(bool with_spheres = true);

// The Utah teapot (Martin Newell, 1975) from its 32 bicubic Bezier patches, each patch tessellated into
// resolution x resolution quads = 2 * resolution^2 triangles; 32 * 2 * resolution^2 triangles in all.
// Order: patch by patch in the classic data's order, rows in v, columns in u, each quad's two triangles.
// Degenerate triangles at the lid and bottom poles are kept (they are part of the classic mesh).
// Layout: each patch has its own (resolution+1)^2 grid of vertices (row j at v = j/res, column i at
// u = i/res; seams are duplicated, not welded); quad (i, j) with corners a = (i, j), b = (i+1, j),
// c = (i+1, j+1), d = (i, j+1) gives (a b c) then (a c d), facing outwards on the body. The data is z-up and
// is turned y-up: (x, y, z) -> (x, z, -y). The result stands on y = 0: x in [-3, 3.434] (handle to spout),
// y in [0, 3.15], z in [-2, 2]. Resolution 10 reproduces ../shared/scenes/teapot.obj (less its degenerates).
// Throws std::invalid_argument for a resolution below 1.
triangle_mesh teapot_mesh(int resolution);

// The teapot on a ground plane with a light and camera (a diffuse teapot and plane).
// Name "teapot"; material 0 the teapot, 1 the ground plane y = 0; the camera frames the teapot from 20
// degrees above the horizontal, the light as frame_light places it.
scene teapot_scene(int resolution = 8);

// The teapot in a stadium (Haines): a small, finely tessellated teapot at the centre of a huge, coarsely
// tessellated stadium bowl: many triangles in a tiny part of space, the case that breaks uniform grids.
// The teapot's triangles come first, then the stadium's. The camera looks at the teapot.
// Stadium: a field (disc of radius 320 at y = 0, a fan of `stadium_segments` triangles), then 12 tiers
// outwards, each segment by segment as a riser (2 triangles, facing the centre) and a tread (2 triangles,
// facing up). Materials: 0 for the teapot, 1 for the stadium (triangle_materials is filled).
scene teapot_in_stadium(int teapot_resolution = 8, int stadium_segments = 64);

// Unit sphere at the origin as a UV sphere of `stacks` x `slices` quads (poles as single triangles).
// 2 * slices * (stacks - 1) triangles, counter-clockwise seen from outside, in the order: north cap fan,
// the bands of quads from north to south (2 triangles per quad), south cap fan. Needs stacks >= 2, slices >= 3.
triangle_mesh tessellated_sphere(int stacks, int slices);

// count triangles with vertices uniform in the unit cube... of edge length about `size` each.
// Triangle i: a centre uniform in [size/2, 1 - size/2]^3, then three vertices within size/2 of it per axis,
// all from one pcg32(seed) stream; every vertex lies in the unit cube. 3 * count vertices, none shared.
triangle_mesh random_soup(std::size_t count, std::uint64_t seed, float size = 0.05f);

// count triangles gathered in `clusters` tight Gaussian-like clumps inside the unit cube.
// Cluster centres uniform in [0.15, 0.85]^3; each triangle picks a cluster at random, its centre lies about
// it with a standard deviation of 0.05 per axis (clamped to the cube), its vertices as in random_soup.
// Throws std::invalid_argument for clusters < 1.
triangle_mesh clustered_soup(std::size_t count, std::uint64_t seed, int clusters = 8, float size = 0.01f);

// Wraps a mesh into a scene with one diffuse material, a framing camera and a light (as load_scene does).
scene mesh_scene(std::string name, triangle_mesh mesh);

// Names accepted by builtin_scene(): cornell, teapot, teapot_stadium, sphere, soup, clustered_soup,
// teapot_field. They are: cornell_box(true), teapot_scene(8), teapot_in_stadium(8, 64),
// tessellated_sphere(32, 64), random_soup(10000, 1), clustered_soup(10000, 1), and an instanced scene
// (instancing.hpp): make_field(teapot_mesh(4), 5 x 5, spacing 1.5), 25 teapots of 1,024 triangles; each
// scene's name is its builtin name.
std::vector<std::string> builtin_scene_names();
scene builtin_scene(const std::string& name);  // throws std::invalid_argument for an unknown name

}  // namespace strahl
