// The exact reference of the two-level BVH (two_level.hpp): every instance in order, the ray moved into its
// object space by exercise 10.1's function with the same matrices, every triangle with chapter 01's test.
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch10/object_ray.hpp"
#include "strahl/ch10/two_level.hpp"
#include <stdexcept>

namespace strahl::ch10 {

void instanced_brute::build(const instanced_meshes& scene) {
    meshes_.assign(scene.meshes.size(), {});
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const triangle_mesh& mesh = scene.meshes[m];
        meshes_[m].resize(mesh.triangle_count());
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i) meshes_[m][i] = mesh.triangle(i);
    }
    const std::vector<std::uint32_t> first = scene.first_ids();
    instances_.clear();
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const std::optional<affine> inv = inverse(scene.instances[i].to_world);
        if (!inv) throw std::invalid_argument("instanced_brute: an instance's transform is not invertible");
        instances_.push_back({scene.instances[i].mesh, first[i], scene.instances[i].to_world.is_identity(), *inv});
    }
    bounds_ = scene.bounds();
}

template <class Stats>
hit instanced_brute::closest(const ray& query, Stats& stats) const {
    stats.ray();
    hit best;
    ray r = query;
    for (std::uint32_t k = 0; k < instances_.size(); ++k) {
        const inst& in = instances_[k];
        ray o = in.identity ? r : to_object(r, in.to_object);
        o.tmax = r.tmax;
        const auto& tris = meshes_[in.mesh];
        for (std::uint32_t id = 0; id < tris.size(); ++id) {
            float t, u, v;
            stats.prim_test();
            if (ch01::intersect_triangle(o, tris[id][0], tris[id][1], tris[id][2], t, u, v) &&
                ch01::record_closest(in.first_id + id, t, u, v, o, best))
                best.inst = k;
        }
        r.tmax = o.tmax;
    }
    return best;
}

template <class Stats>
bool instanced_brute::any(const ray& query, Stats& stats) const {
    stats.ray();
    for (const inst& in : instances_) {
        ray o = in.identity ? query : to_object(query, in.to_object);
        o.tmax = query.tmax;
        for (const auto& tri : meshes_[in.mesh]) {
            float t, u, v;
            stats.prim_test();
            if (ch01::intersect_triangle(o, tri[0], tri[1], tri[2], t, u, v)) return true;
        }
    }
    return false;
}

std::size_t instanced_brute::memory_bytes() const {
    std::size_t bytes = instances_.size() * sizeof(inst);
    for (const auto& m : meshes_) bytes += m.size() * sizeof(m[0]);
    return bytes;
}

template hit instanced_brute::closest(const ray&, not_counting&) const;
template hit instanced_brute::closest(const ray&, counting&) const;
template bool instanced_brute::any(const ray&, not_counting&) const;
template bool instanced_brute::any(const ray&, counting&) const;

}  // namespace strahl::ch10
