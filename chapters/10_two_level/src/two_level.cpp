// The two-level BVH (two_level.hpp): build, updates, and the any-hit walk through both levels. The
// closest-hit walk is exercise 10.3 (exercises/10_two_level/instance_walk.cpp); any() below is its model.
#include "strahl/ch10/two_level.hpp"
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch05/fast_traverse.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch10/object_ray.hpp"
#include "strahl/tree_query.hpp"
#include <cmath>
#include <stdexcept>

namespace strahl::ch10 {

namespace {
ch04::bvh binned16(std::span<const aabb> b, std::span<const vec3> c) {
    return ch05::build_sah_bvh_fast(b, c, ch05::sah_build_params{});
}
}  // namespace

two_level_config default_config() { return {binned16, binned16}; }

const char* to_string(mesh_update u) {
    switch (u) {
    case mesh_update::refit: return "refit";
    case mesh_update::partial: return "partial";
    case mesh_update::rebuild: return "rebuild";
    }
    return "?";
}

instanced_meshes instances_of(const scene& s) {
    if (s.instances) return *s.instances;
    instanced_meshes one;
    one.meshes.push_back(s.mesh);
    one.names.push_back(s.name);
    one.instances.push_back({0, affine{}});
    return one;
}

namespace {
std::vector<aabb> triangle_boxes(const std::vector<std::array<vec3, 3>>& tris) {
    std::vector<aabb> boxes(tris.size());
    for (std::size_t i = 0; i < tris.size(); ++i) boxes[i].grow(tris[i][0]).grow(tris[i][1]).grow(tris[i][2]);
    return boxes;
}
std::vector<vec3> centroids_of(std::span<const aabb> boxes) {
    std::vector<vec3> c(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) c[i] = boxes[i].centroid();
    return c;
}
// A bound on the condition number of L (Frobenius norms of L and of its inverse): how much the rounding of
// the object-space ray can be magnified back in world space.
float condition(const affine& a, const affine& inv) {
    const auto norm = [](const affine& m) {
        double s = 0.0;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) s += double(m.m[r][c]) * m.m[r][c];
        return std::sqrt(s);
    };
    return float(norm(a) * norm(inv));
}
bool all_finite(std::span<const vec3> p) {
    for (const vec3& v : p)
        if (!is_finite(v)) return false;
    return true;
}
}  // namespace

void two_level::build_mesh(mesh_data& m) {
    m.triangles.resize(m.indices.size());
    for (std::size_t i = 0; i < m.indices.size(); ++i)
        m.triangles[i] = {m.positions[m.indices[i].x], m.positions[m.indices[i].y], m.positions[m.indices[i].z]};
    const std::vector<aabb> boxes = triangle_boxes(m.triangles);
    m.tree = config_.mesh_builder(boxes, centroids_of(boxes));
    m.baseline = subtree_costs(m.tree);
    m.box = aabb();
    for (const aabb& b : boxes) m.box.grow(b);
}

// The instance's world box: its mesh tree's box through to_world, grown by a pad. The top level's box test
// uses the world ray, the bottom level's the object-space ray; the two roundings may differ by a few units
// in the last place of the scene's coordinates, times how much the transform stretches one direction
// against another (its condition number). The pad covers that 2^6 times over, so no hit the object-space
// test finds lies outside its instance's box.
void two_level::update_instance(instance_data& inst, const affine& to_world) {
    const std::optional<affine> inv = inverse(to_world);
    if (!inv) throw std::invalid_argument("two_level: an instance's transform is not invertible");
    inst.to_world = to_world;
    inst.to_object = *inv;
    inst.identity = to_world.is_identity();
    const aabb& box = meshes_[inst.mesh].tree.bounds;
    inst.world_box = transformed(box, to_world);
    if (!inst.world_box.is_empty() && !inst.identity) {
        const vec3 far = glm::max(glm::abs(inst.world_box.min), glm::abs(inst.world_box.max));
        const float scale = std::max({far.x, far.y, far.z}) + glm::length(inst.world_box.extent());
        inst.world_box = grown(inst.world_box, 0x1p-18f * condition(to_world, *inv) * scale);
    }
}

void two_level::build_top(bool refit_only) {
    std::vector<aabb> boxes(instances_.size());
    bounds_ = aabb();
    for (std::size_t i = 0; i < instances_.size(); ++i) boxes[i] = instances_[i].world_box;
    if (refit_only && !top_.nodes.empty()) {
        refit(top_, boxes);
    } else {
        top_ = config_.top_builder(boxes, centroids_of(boxes));
    }
    // The frame's box, as the instanced description's bounds() computes it: each mesh's box (of its
    // triangles' corners) transformed.
    for (const instance_data& inst : instances_) bounds_.grow(transformed(meshes_[inst.mesh].box, inst.to_world));
}

void two_level::build(const instanced_meshes& scene) {
    meshes_.assign(scene.meshes.size(), {});
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        meshes_[m].positions = scene.meshes[m].positions;
        meshes_[m].indices = scene.meshes[m].indices;
        build_mesh(meshes_[m]);
    }
    const std::vector<std::uint32_t> first = scene.first_ids();
    instances_.assign(scene.instances.size(), {});
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        instances_[i].mesh = scene.instances[i].mesh;
        instances_[i].first_id = first[i];
        update_instance(instances_[i], scene.instances[i].to_world);
    }
    build_top(false);
}

void two_level::set_transforms(std::span<const affine> to_world, bool refit_top) {
    if (to_world.size() != instances_.size())
        throw std::invalid_argument("two_level: " + std::to_string(to_world.size()) + " transforms for " +
                                    std::to_string(instances_.size()) + " instances");
    for (std::size_t i = 0; i < instances_.size(); ++i)  // all checked before any is changed
        if (!inverse(to_world[i]))
            throw std::invalid_argument("two_level: instance " + std::to_string(i) + "'s transform is not invertible");
    for (std::size_t i = 0; i < instances_.size(); ++i) update_instance(instances_[i], to_world[i]);
    build_top(refit_top);
}

partial_result two_level::set_vertices(std::uint32_t mesh, std::span<const vec3> positions, mesh_update how,
                                       const partial_params& params, bool top) {
    if (mesh >= meshes_.size()) throw std::invalid_argument("two_level: no mesh " + std::to_string(mesh));
    mesh_data& m = meshes_[mesh];
    if (positions.size() != m.positions.size())
        throw std::invalid_argument("two_level: " + std::to_string(positions.size()) + " vertices for a mesh of " +
                                    std::to_string(m.positions.size()));
    m.positions.assign(positions.begin(), positions.end());
    partial_result result;
    // A vertex outside the finite range, or loose triangles from the last build: only a rebuild places them.
    if (!all_finite(positions) || !m.tree.loose.empty()) how = mesh_update::rebuild;
    if (how == mesh_update::rebuild) {
        build_mesh(m);
        result.full = true;
    } else {
        for (std::size_t i = 0; i < m.indices.size(); ++i)
            m.triangles[i] = {m.positions[m.indices[i].x], m.positions[m.indices[i].y], m.positions[m.indices[i].z]};
        const std::vector<aabb> boxes = triangle_boxes(m.triangles);
        m.box = aabb();
        for (const aabb& b : boxes) m.box.grow(b);
        refit(m.tree, boxes);
        if (how == mesh_update::partial) result = partial_rebuild(m.tree, m.baseline, boxes, config_.mesh_builder, params);
    }
    for (instance_data& inst : instances_)
        if (inst.mesh == mesh) update_instance(inst, inst.to_world);
    if (top) build_top(false);
    return result;
}

std::size_t two_level::memory_bytes() const {
    std::size_t bytes = top_.memory_bytes() + instances_.size() * sizeof(instance_data);
    for (const mesh_data& m : meshes_)
        bytes += m.tree.memory_bytes() + m.tree.loose.size() * 4 + m.triangles.size() * sizeof(m.triangles[0]);
    return bytes;
}

double two_level::mesh_cost(std::uint32_t m) const { return ch04::sah_tree_cost(meshes_.at(m).tree, 1.0f, 1.0f); }
double two_level::top_cost() const { return ch04::sah_tree_cost(top_, 1.0f, 1.0f); }

double two_level::sah_cost() const {
    if (top_.nodes.empty()) return 0.0;
    const double root = top_.bounds.surface_area();
    const auto ratio = [&](const aabb& b) { return root > 0.0 ? double(b.surface_area()) / root : 1.0; };
    double cost = 0.0;
    for (const ch04::bvh_node& n : top_.nodes)
        if (!n.is_leaf()) cost += ratio(n.box());
    for (std::uint32_t id : top_.prim_ids) {
        const instance_data& inst = instances_[id];
        cost += ratio(inst.identity ? meshes_[inst.mesh].tree.bounds : inst.world_box) * mesh_cost(inst.mesh);
    }
    return cost;
}

// ---- The walk, any hit ----

// Whether instance k's mesh blocks the world ray r: the ray moved into object space, chapter 05's walk
// through the mesh's tree, stopped at the first triangle hit.
template <class Stats>
bool two_level::blocks(std::uint32_t k, const ray& r, Stats& stats) const {
    const instance_data& inst = instances_[k];
    const mesh_data& m = meshes_[inst.mesh];
    ray o = inst.identity ? r : to_object(r, inst.to_object);
    o.tmax = r.tmax;
    const auto test = [&](std::uint32_t id) {
        float t, u, v;
        stats.prim_test();
        const auto& tri = m.triangles[id];
        return ch01::intersect_triangle(o, tri[0], tri[1], tri[2], t, u, v);
    };
    for (const std::uint32_t id : m.tree.loose)
        if (test(id)) return true;
    if (!placeable(o)) {
        for (std::uint32_t id = 0; id < m.triangles.size(); ++id)
            if (test(id)) return true;
        return false;
    }
    bool found = false;
    if (!m.tree.nodes.empty())
        ch05::fast_traverse(m.tree, o, stats, [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t j = 0; j < count && !found; ++j) found = test(m.tree.prim_ids[first + j]);
            return found;
        });
    return found;
}

template <class Stats>
bool two_level::any(const ray& query, Stats& stats) const {
    stats.ray();
    if (!(query.tmin < query.tmax)) return false;
    if (!placeable(query)) {
        for (std::uint32_t k = 0; k < instances_.size(); ++k)
            if (blocks(k, query, stats)) return true;
        return false;
    }
    for (const std::uint32_t k : top_.loose)
        if (blocks(k, query, stats)) return true;
    bool found = false;
    ray r = query;
    if (!top_.nodes.empty())
        ch05::fast_traverse(top_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t j = 0; j < count && !found; ++j) found = blocks(top_.prim_ids[first + j], query, stats);
            return found;
        });
    return found;
}

template bool two_level::any(const ray&, not_counting&) const;
template bool two_level::any(const ray&, counting&) const;

}  // namespace strahl::ch10
