// Steps 1, 3 and 4 (compiled here, apart from the exercises: the triangle test is a call into another
// file), the step table, and the renderer over step 1 with chapter 01's virtual materials.
#include "strahl/ch11/materials.hpp"
#include "strahl/ch11/render.hpp"
#include <stdexcept>

namespace strahl::ch11 {

namespace {
constexpr step_info step_table[] = {
    {step::virtual_calls, "virtual", "chapter 01's objects: a heap object and a virtual call per primitive"},
    {step::variant, "variant", "a std::variant of the primitive types in one array, std::visit per primitive"},
    {step::type_sorted, "type-sorted", "one array per type in leaf order, a range per type per leaf"},
    {step::triangles_only, "triangles", "triangles only, edges precomputed, in leaf order; the test a call"},
    {step::inlined, "inlined", "the same, the triangle test inlined into the walk"},
    {step::soa, "soa", "the same, the triangles as a structure of arrays"},
};
constexpr renderer renderer_table[] = {
    {"virtual", step::virtual_calls, shading::virtual_calls},
    {"variant", step::variant, shading::variant},
    {"triangles+virtual", step::soa, shading::virtual_calls},
    {"triangles+switch", step::soa, shading::switch_id},
};
}  // namespace

std::span<const step_info> all_steps() { return step_table; }

const step_info& info(step s) {
    for (const step_info& i : step_table)
        if (i.id == s) return i;
    throw std::invalid_argument("chapter 11: no such step");
}

const char* to_string(shading m) {
    switch (m) {
    case shading::virtual_calls: return "virtual";
    case shading::variant: return "variant";
    default: return "switch";
    }
}

std::span<const renderer> all_renderers() { return renderer_table; }

ch04::bvh build_tree(std::span<const aabb> boxes) {
    std::vector<vec3> centroids(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) centroids[i] = boxes[i].centroid();
    return ch05::build_sah_bvh_fast(boxes, centroids);
}

// ---- Step 1 ----

virtual_set::virtual_set(const std::vector<shape>& shapes) {
    objects_.reserve(shapes.size());
    struct visitor {
        std::unique_ptr<ch01::primitive> operator()(const triangle_shape& t) const {
            return std::make_unique<ch01::triangle>(t.v0, t.v1, t.v2);
        }
        std::unique_ptr<ch01::primitive> operator()(const sphere_shape& s) const {
            return std::make_unique<ch01::sphere>(s.center, s.radius);
        }
        std::unique_ptr<ch01::primitive> operator()(const plane_shape& p) const {
            return std::make_unique<ch01::plane>(p.normal, p.offset);
        }
    };
    for (const shape& s : shapes) objects_.push_back(std::visit(visitor{}, s));
}

std::size_t virtual_set::memory_bytes() const {
    // The owning pointers and the objects (chapter 01's triangle is the largest: vtable, material, 4 vec3).
    return objects_.size() * (sizeof(void*) + sizeof(ch01::triangle));
}

// ---- Step 3 ----

void sorted_accel::build(const scene& s) {
    shapes_by_id_ = shapes_of(s);
    std::vector<aabb> boxes(shapes_by_id_.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = ch11::bounds(shapes_by_id_[i]);
    tree_ = build_tree(boxes);
    prims_ = {};
    leaves_.clear();
    loose_.clear();
    // Exercise 11.3 per leaf, in the tree's order; each leaf node's offset becomes its index in leaves_.
    for (ch04::bvh_node& n : tree_.nodes) {
        if (!n.is_leaf()) continue;
        const std::span<const std::uint32_t> ids(tree_.prim_ids.data() + n.offset, n.count);
        leaves_.push_back(sort_leaf_by_type(ids, shapes_by_id_, prims_));
        n.offset = std::uint32_t(leaves_.size() - 1);
    }
    // The loose primitives at the ends of the arrays, as one more (never walked) leaf.
    const sorted_leaf loose = sort_leaf_by_type(tree_.loose, shapes_by_id_, prims_);
    const std::size_t n_tri = prims_.triangles.size(), n_sph = prims_.spheres.size();
    for (std::uint32_t k = 0; k < loose.count[0]; ++k) loose_.push_back(loose.first[0] + k);
    for (std::uint32_t k = 0; k < loose.count[1]; ++k) loose_.push_back(std::uint32_t(n_tri + loose.first[1] + k));
    for (std::uint32_t k = 0; k < loose.count[2]; ++k)
        loose_.push_back(std::uint32_t(n_tri + n_sph + loose.first[2] + k));
    std::size_t total = 0;
    for (const auto& v : prims_.ids) total += v.size();
    if (total != shapes_by_id_.size())
        throw std::logic_error("chapter 11: the type-sorted arrays hold " + std::to_string(total) + " primitives, the scene " +
                               std::to_string(shapes_by_id_.size()));
}

std::size_t sorted_accel::slot_count() const {
    return prims_.triangles.size() + prims_.spheres.size() + prims_.planes.size();
}

std::uint32_t sorted_accel::slot_id(std::uint32_t k) const {
    const std::size_t n_tri = prims_.triangles.size(), n_sph = prims_.spheres.size();
    if (k < n_tri) return prims_.ids[0][k];
    if (k < n_tri + n_sph) return prims_.ids[1][k - n_tri];
    return prims_.ids[2][k - n_tri - n_sph];
}

bool sorted_accel::test_slot(std::uint32_t k, const ray& r, float& t, float& u, float& v) const {
    const std::size_t n_tri = prims_.triangles.size(), n_sph = prims_.spheres.size();
    if (k < n_tri) {
        const triangle_shape& tri = prims_.triangles[k];
        return ch01::intersect_triangle(r, tri.v0, tri.v1, tri.v2, t, u, v);
    }
    u = v = 0.0f;
    if (k < n_tri + n_sph) return ch01::intersect_sphere(r, prims_.spheres[k - n_tri].center, prims_.spheres[k - n_tri].radius, t);
    const plane_shape& p = prims_.planes[k - n_tri - n_sph];
    return ch01::intersect_plane(r, p.normal, p.offset, t);
}

// ---- The steps by number ----

std::unique_ptr<step_accel> make_accel(step s, bool with_shapes) {
    switch (s) {
    case step::virtual_calls: return std::make_unique<indexed_accel<virtual_set>>(s, with_shapes);
    case step::variant: return make_variant_accel(with_shapes);
    case step::type_sorted: return std::make_unique<sorted_accel>(s, with_shapes);
    case step::triangles_only: return std::make_unique<triangles_accel>(s, with_shapes);
    case step::inlined:
    case step::soa: return make_inlined_accel(s, with_shapes);
    }
    throw std::invalid_argument("chapter 11: no such step");
}

// ---- Rendering ----

ch01::render_result render_virtual(const scene& s, const camera& cam, const ch01::render_settings& settings, int glossy) {
    indexed_accel<virtual_set> tracer(step::virtual_calls, true);
    tracer.build(s);
    return render_with(tracer, make_virtual_materials(s, glossy), s.lights, cam, settings);
}

ch01::render_result render(const scene& s, const camera& cam, const renderer& how, const ch01::render_settings& settings,
                           int glossy_samples) {
    if (how.tracer == step::virtual_calls) return render_virtual(s, cam, settings, glossy_samples);
    if (how.tracer == step::variant) return render_variant(s, cam, settings, glossy_samples);
    return render_triangles(s, cam, how.materials, settings, glossy_samples);
}

}  // namespace strahl::ch11
