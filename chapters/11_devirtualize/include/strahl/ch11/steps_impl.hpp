// Steps 2, 5 and 6, and the renderers over them, compiled in the same file as exercises 11.1 and 11.2
// (included at the end of leaf_tests.cpp): the variant's visit and the triangle test are inlined into
// their walks here. Step 4 is the same code as step 5 compiled in src/steps.cpp, where the test is a call.
#pragma once
#include "strahl/ch11/materials.hpp"
#include "strahl/ch11/render.hpp"

namespace strahl::ch11 {

std::unique_ptr<step_accel> make_variant_accel(bool with_shapes) {
    return std::make_unique<indexed_accel<variant_set>>(step::variant, with_shapes);
}

std::unique_ptr<step_accel> make_inlined_accel(step s, bool with_shapes) {
    if (s == step::soa) return std::make_unique<soa_accel>(s, with_shapes);
    return std::make_unique<inlined_accel>(step::inlined, with_shapes);
}

ch01::render_result render_variant(const scene& s, const camera& cam, const ch01::render_settings& settings,
                                   int glossy) {
    indexed_accel<variant_set> tracer(step::variant, true);
    tracer.build(s);
    return render_with(tracer, make_variant_materials(s, glossy), s.lights, cam, settings);
}

ch01::render_result render_triangles(const scene& s, const camera& cam, shading materials,
                                     const ch01::render_settings& settings, int glossy) {
    soa_accel tracer(step::soa, true);
    tracer.build(s);
    if (materials == shading::switch_id)
        return render_with(tracer, make_switch_materials(s, glossy), s.lights, cam, settings);
    if (materials == shading::variant)
        return render_with(tracer, make_variant_materials(s, glossy), s.lights, cam, settings);
    return render_with(tracer, make_virtual_materials(s, glossy), s.lights, cam, settings);
}

}  // namespace strahl::ch11
