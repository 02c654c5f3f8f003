#include "strahl/race/oo_tracer.hpp"
#include "strahl/ch01/world.hpp"

namespace strahl::race {

namespace {

class oo_tracer final : public accel {
public:
    std::string name() const override { return "ch01-virtual"; }

    void build(const scene& s) override {
        scene triangles_only = s;  // the race traces the mesh: spheres and planes stay out
        triangles_only.spheres.clear();
        triangles_only.planes.clear();
        world_ = ch01::build_world(triangles_only);
        frame_ = ray_frame(s.mesh.bounds());  // far origins moved to the scene, as brute force does
        triangle_count_ = s.mesh.triangle_count();
    }

    void intersect(std::span<const ray> rays, std::span<hit> hits) const override { (void)intersect_counted(rays, hits); }
    void occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const override {
        (void)occluded_counted(rays, blocked);
    }

    // The world counts always (chapter 01 counts every test it makes); the race times it the same way.
    std::optional<counter_values> intersect_counted(std::span<const ray> rays, std::span<hit> hits) const override {
        counting c;
        for (std::size_t i = 0; i < rays.size(); ++i)
            hits[i] = frame_.closest(rays[i], [&](const ray& r) {
                ch01::surface s;
                return world_.closest_hit(r, s, c) ? s.h : hit{};
            });
        return c.values();
    }
    std::optional<counter_values> occluded_counted(std::span<const ray> rays,
                                                   std::span<std::uint8_t> blocked) const override {
        counting c;
        for (std::size_t i = 0; i < rays.size(); ++i)
            blocked[i] = frame_.any(rays[i], [&](const ray& r) { return world_.occluded(r, c); }) ? 1 : 0;
        return c.values();
    }

    // One object per triangle: the object (vtable pointer, material id, 3 vertices and a normal) and the
    // owning pointer to it; the allocator's own overhead is not counted.
    std::size_t memory_bytes() const override {
        return triangle_count_ * (sizeof(void*) + sizeof(void*) + sizeof(std::uint32_t) + 12 * sizeof(float));
    }

private:
    ch01::world world_;
    ray_frame frame_;
    std::size_t triangle_count_ = 0;
};

}  // namespace

std::unique_ptr<accel> make_oo_tracer() { return std::make_unique<oo_tracer>(); }

}  // namespace strahl::race
