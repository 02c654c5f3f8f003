// Chapter 11: model only what the scene requires. One tree (chapter 05's binned SAH, walked by chapter 05's
// fast traversal) and the same rays throughout; only how a leaf reaches its primitives changes, step by
// step, each step a structure of its own (the race's rows "ch11-virtual" ... "ch11-soa"):
//   1 virtual        chapter 01's objects: one heap object per primitive, a virtual intersect() per test;
//   2 variant        a closed set of value types in one array (shapes.hpp), std::visit per test;
//   3 type-sorted    one array per type in leaf order, a range per type per leaf (type_sorted.hpp);
//   4 triangles      triangles only, edges precomputed, in leaf order (triangles.hpp); the test a call;
//   5 inlined        the same, with the test compiled into the traversal;
//   6 soa            the same, its triangles as a structure of arrays.
// Every step answers exactly as brute force over chapter 01's objects (the same triangle test).
// And the same steps for shading: chapter 01's Whitted renderer with virtual materials, a variant, and a
// switch over a material id (render()).
#pragma once
#include "strahl/accel.hpp"
#include "strahl/camera.hpp"
#include "strahl/ch01/render.hpp"
#include "strahl/ch04/bvh.hpp"
#include <memory>
#include <span>

namespace strahl::ch11 {

enum class step { virtual_calls = 1, variant, type_sorted, triangles_only, inlined, soa };

struct step_info {
    step id;
    const char* name;  // "virtual", "variant", "type-sorted", "triangles", "inlined", "soa"
    const char* what;  // one line for tables
};
std::span<const step_info> all_steps();
const step_info& info(step s);

// The step's structure behind the course's accel interface. with_shapes: the scene's spheres and planes
// too, with ids after the triangles in chapter 01's order (world.hpp); without, the accel contract's
// triangles only (the race's rows). tree(): the binary tree every step walks (the same for steps 1 to 3;
// over the triangles alone from step 4 on, spheres and planes being traced beside it).
class step_accel : public accel {
public:
    virtual const ch04::bvh& tree() const = 0;
};
std::unique_ptr<step_accel> make_accel(step s, bool with_shapes = false);

// ---- Shading ----

enum class shading { virtual_calls, variant, switch_id };
const char* to_string(shading m);  // "virtual", "variant", "switch"

// A renderer: which step's structure finds the hits, which material form shades them.
struct renderer {
    const char* name;  // "virtual", "variant", "triangles+virtual", "triangles+switch"
    step tracer;
    shading materials;
};
std::span<const renderer> all_renderers();

// Chapter 01's renderer (render.hpp: tiles seeded by index, Whitted shading, rough mirrors with
// glossy_samples rays) over the scene's triangles, spheres and planes, through the renderer's structure and
// materials. The image equals chapter 01's brute-force render bit for bit. result.seconds: the render
// alone, after the structure is built.
ch01::render_result render(const scene& s, const camera& cam, const renderer& how, const ch01::render_settings& settings,
                           int glossy_samples);

}  // namespace strahl::ch11
