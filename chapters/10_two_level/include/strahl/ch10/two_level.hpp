// The two-level BVH: one bottom-level BVH per mesh, in the mesh's own (object) space, and a top-level BVH
// over the instances' world boxes. At an instance the ray moves into object space (exercise 10.1) and walks
// the mesh's tree; the hit carries the instance. Rigid motion changes only the top level; a deforming mesh
// changes only its own tree (refit, partial or full rebuild: refit.hpp).
//   I. Wald, C. Benthin and P. Slusallek, "A simple and practical method for interactive ray tracing of
//   dynamic scenes", technical report, Saarland University, 2002 (two levels: rebuild the top, keep the rest);
//   pbrt-v4, section 7.1.5 (instances).
// Both levels are chapter 04's flat tree, walked by chapter 05's fast traversal.
#pragma once
#include "strahl/ch04/accel.hpp"
#include "strahl/ch10/refit.hpp"
#include "strahl/instancing.hpp"
#include "strahl/stats.hpp"
#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace strahl::ch10 {

struct two_level_config {
    ch04::bvh_builder mesh_builder;  // bottom levels (default: chapter 05's 16-bin SAH, fast builder)
    ch04::bvh_builder top_builder;   // the top level (default: the same)
};
two_level_config default_config();

enum class mesh_update { refit, partial, rebuild };
const char* to_string(mesh_update u);

class two_level {
public:
    explicit two_level(two_level_config config = default_config()) : config_(std::move(config)) {}

    // Builds every mesh's tree and the top level. A scene without instances is one instance of scene.mesh.
    void build(const instanced_meshes& scene);

    // Rigid motion: instance i gets to_world[i] (invertible, finite: else std::invalid_argument); the top
    // level is rebuilt (or, refit_top, refit: its topology kept).
    void set_transforms(std::span<const affine> to_world, bool refit_top = false);

    // Deformation: mesh m's vertices replaced (same count: else std::invalid_argument); its tree refit,
    // partially rebuilt or rebuilt (always rebuilt where a vertex is not finite); the instances' world boxes
    // follow, and the top level is rebuilt unless top is false (a set_transforms call follows in the frame).
    partial_result set_vertices(std::uint32_t mesh, std::span<const vec3> positions, mesh_update how,
                                const partial_params& params = {}, bool top = true);

    template <class Stats>
    hit closest(const ray& r, Stats& stats) const;
    template <class Stats>
    bool any(const ray& r, Stats& stats) const;

    // Bytes held: the meshes' triangles and trees, the instances, the top level.
    std::size_t memory_bytes() const;
    // SAH cost (chapter 05's, normalised) of mesh m's tree, and of the top level alone (an instance counted
    // as one primitive).
    double mesh_cost(std::uint32_t m) const;
    double top_cost() const;
    // The whole structure's, in world space: C_T times the top level's inner nodes' areas over the root's,
    // plus for each instance the chance of meeting its world box (its area over the root's) times its mesh
    // tree's cost. (An affine map does not keep ratios of areas, so the mesh's cost is its object-space one:
    // exact for rotations, translations and uniform scales.) A plain scene's: its tree's cost.
    double sah_cost() const;
    aabb bounds() const { return bounds_; }  // instanced_meshes::bounds() of what it holds (the ray frame's box)
    std::size_t instance_count() const { return instances_.size(); }
    std::size_t mesh_count() const { return meshes_.size(); }

private:
    struct mesh_data {
        std::vector<vec3> positions;
        std::vector<uvec3> indices;
        std::vector<std::array<vec3, 3>> triangles;  // the leaf test's copy, as chapter 01's triangle_set
        ch04::bvh tree;
        std::vector<float> baseline;  // per node: subtree cost at its last build (partial rebuild)
        aabb box;                     // of its triangles' corners (the ray frame's part)
    };
    struct instance_data {
        std::uint32_t mesh;
        std::uint32_t first_id;  // the flattened id of its first triangle
        bool identity;           // to_world is the identity: the world ray is used as it is
        affine to_world, to_object;
        aabb world_box;          // the mesh tree's box, transformed and grown by pad (see .cpp)
    };
    void build_mesh(mesh_data& m);
    void update_instance(instance_data& inst, const affine& to_world);
    void build_top(bool refit);

    template <class Stats>
    void visit(std::uint32_t k, ray& r, hit& best, Stats& stats) const;
    template <class Stats>
    bool blocks(std::uint32_t k, const ray& r, Stats& stats) const;

    two_level_config config_;
    std::vector<mesh_data> meshes_;
    std::vector<instance_data> instances_;
    ch04::bvh top_;
    aabb bounds_;
};

// The exact reference: every instance in order, the ray moved into its object space by to_object (the same
// function and matrices as the two-level structure), every triangle of its mesh with chapter 01's test.
class instanced_brute {
public:
    void build(const instanced_meshes& scene);
    template <class Stats>
    hit closest(const ray& r, Stats& stats) const;
    template <class Stats>
    bool any(const ray& r, Stats& stats) const;
    std::size_t memory_bytes() const;
    aabb bounds() const { return bounds_; }

private:
    struct inst {
        std::uint32_t mesh, first_id;
        bool identity;
        affine to_object;
    };
    std::vector<std::vector<std::array<vec3, 3>>> meshes_;
    std::vector<inst> instances_;
    aabb bounds_;
};

// A scene's instances, or one identity instance of its mesh when it has none.
instanced_meshes instances_of(const scene& s);

}  // namespace strahl::ch10
