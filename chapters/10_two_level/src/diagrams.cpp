// The chapter's figure, computed by the chapter's own code (`ch10 --diagrams DIR`):
//   instances.svg: one small mesh (a house of three triangles in the plane z = 0) placed three times by
//   rotations, scales and moves; seen from above, the instances' world boxes under the top level's root box
//   and a world ray coming down onto one of them (left); the same ray moved into that instance's object
//   space (to_object, exercise 10.1) over the mesh's own tree, chapter 05's binned SAH (right). The marks at
//   t = 1, 2, 3 and the hit sit on the same points of the mesh in both spaces: the direction is not
//   normalised, so t carries over.
#include "strahl/ch05/sah.hpp"
#include "strahl/ch10/object_ray.hpp"
#include "strahl/ch10/two_level.hpp"
#include "strahl/diagram.hpp"
#include "strahl/instancing.hpp"
#include <cstdio>
#include <string>
#include <vector>

namespace strahl::ch10 {

namespace {

// The ray's path from t = 0 to t = t_end (seen from above), marks at t = 1, 2, ... and at the hit.
void draw_ray(diagram& d, const ray& r, float t_end, float t_hit, const char* colour) {
    const vec3 a = r.org, b = r.org + t_end * r.dir;
    d.arrow(a.x, a.y, b.x, b.y, {colour, "none", 2.0});
    for (int t = 1; float(t) < t_end; ++t) {
        const vec3 p = r.org + float(t) * r.dir;
        d.circle(p.x, p.y, 4, {colour, "white", 1.5});
        d.text(p.x + 7 / d.scale(), p.y + 6 / d.scale(), "t = " + std::to_string(t), {11, "start", colour, false, true});
    }
    const vec3 h = r.org + t_hit * r.dir;
    d.circle(h.x, h.y, 6, {ink::red, ink::red, 1.5});
}

diagram instances_figure() {
    // The mesh: a house (a square of two triangles and a roof) in object space, z = 0.
    triangle_mesh house;
    house.positions = {vec3(0, 0, 0), vec3(2, 0, 0), vec3(2, 2, 0), vec3(0, 2, 0), vec3(1, 3.2f, 0)};
    house.indices = {uvec3(0, 1, 2), uvec3(0, 2, 3), uvec3(3, 2, 4)};
    const affine to_world[3] = {
        affine::translate({1.0f, 1.0f, 0}) * affine::rotate(2, 20.0f) * affine::scale(vec3(0.8f)),
        affine::translate({5.5f, 1.5f, 0}) * affine::rotate(2, -35.0f) * affine::scale(vec3(1.3f)),
        affine::translate({4.0f, 5.5f, 0}) * affine::rotate(2, 90.0f) * affine::scale({0.6f, 1.0f, 1.0f})};
    // A world ray from above the plane down onto it: it reaches z = 0 at t = 4.
    const ray world{vec3(1.2f, 7.2f, 2.0f), vec3(1.35f, -1.2f, -0.5f)};

    // The closest hit over the instances: the chapter's oracle, the instanced brute force.
    instanced_meshes scene;
    scene.meshes = {house};
    scene.names = {"house"};
    for (const affine& a : to_world) scene.instances.push_back({0, a});
    instanced_brute brute;
    brute.build(scene);
    not_counting no_stats;
    const hit h = brute.closest(world, no_stats);
    const int hit_instance = h.found() ? int(h.inst) : -1;
    const float t_hit = h.t;
    const ray object_ray = h.found() ? to_object(world, *inverse(to_world[hit_instance])) : world;

    diagram d(1000, 470);
    const font title{15, "middle", ink::black, true}, body{13, "middle"};
    d.text(240, 24, "world space, from above: three instances, one mesh", title);
    d.text(740, 24, "object space of the instance hit", title);
    // Left: the instances' triangles and world boxes, the top level's root box, the world ray.
    d.view(0, 0, 8, 8, 30, 40, 400, 380);
    aabb root;
    const char* colours[] = {ink::blue, ink::green, ink::purple};
    const char* pale[] = {ink::pale_blue, ink::pale_green, ink::pale_purple};
    for (int k = 0; k < 3; ++k) {
        for (std::size_t f = 0; f < house.indices.size(); ++f) {
            const std::array<vec3, 3> tri = house.triangle(f);
            std::vector<point2> corners;
            for (const vec3& p : tri) {
                const vec3 w = to_world[k].point(p);
                corners.push_back({w.x, w.y});
            }
            d.polygon(corners, {colours[k], pale[k], 1.2});
        }
        const aabb box = transformed(house.bounds(), to_world[k]);
        root.grow(box);
        d.rect(box.min.x, box.min.y, box.max.x, box.max.y, {colours[k], "none", 1.5, true});
    }
    d.rect(root.min.x - 0.08, root.min.y - 0.08, root.max.x + 0.08, root.max.y + 0.08, {ink::black, "none", 1.5, true});
    if (hit_instance >= 0) draw_ray(d, world, t_hit + 0.6f, t_hit, ink::black);
    d.pixels();
    d.text(240, 440, "dashed: the instances' world boxes and the top level's root", body);
    d.text(240, 458, "red: the closest hit, t = " + number_text(t_hit), body);

    // Right: the mesh in object space, its tree's boxes, the object ray.
    if (hit_instance >= 0) {
        std::vector<aabb> boxes;
        std::vector<vec3> centroids;
        for (std::size_t f = 0; f < house.indices.size(); ++f) {
            const std::array<vec3, 3> tri = house.triangle(f);
            aabb b;
            for (const vec3& p : tri) b.grow(p);
            boxes.push_back(b);
            centroids.push_back(b.centroid());
        }
        ch05::sah_build_params one_per_leaf;
        one_per_leaf.max_leaf = 1;
        const ch04::bvh tree = ch05::build_sah_bvh_fast(boxes, centroids, one_per_leaf);
        aabb window = house.bounds();
        window.grow(object_ray.org).grow(object_ray.org + (t_hit + 0.6f) * object_ray.dir);
        d.view(window.min.x - 0.5, window.min.y - 0.5, window.max.x + 0.5, window.max.y + 0.5, 520, 40, 440, 380);
        for (std::size_t f = 0; f < house.indices.size(); ++f) {
            const std::array<vec3, 3> tri = house.triangle(f);
            d.polygon({{tri[0].x, tri[0].y}, {tri[1].x, tri[1].y}, {tri[2].x, tri[2].y}},
                      {colours[hit_instance], pale[hit_instance], 1.2});
        }
        for (const ch04::bvh_node& n : tree.nodes)
            d.rect(n.bmin[0] - 0.04, n.bmin[1] - 0.04, n.bmax[0] + 0.04, n.bmax[1] + 0.04, {ink::orange, "none", 1.5, true});
        draw_ray(d, object_ray, t_hit + 0.6f, t_hit, ink::black);
        d.pixels();
        d.text(740, 440, "the same ray through to_object (its direction not normalised)", body);
        d.text(740, 458, "orange: the mesh's own tree, shared by every instance", body);
    }
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"instances.svg", instances_figure}});
}

}  // namespace strahl::ch10
