// Exercise 01.4 Whitted shading (5 points). Worlds are built from planes (chapter code) and a sphere
// derived here, so these tests need none of the other exercises.
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch01/whitted.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch01;

namespace {

// An occluder for the shadow tests: a sphere with its own intersection code (not exercise 01.2's).
class test_ball final : public primitive {
public:
    test_ball(vec3 c, float r, std::uint32_t m) : primitive(m), c_(c), r_(r) {}
    bool intersect(const ray& r, hit& h) const override {
        const vec3 f = r.org - c_;
        const double a = glm::dot(r.dir, r.dir), b = glm::dot(f, r.dir), c = double(glm::dot(f, f)) - r_ * r_;
        const double disc = b * b - a * c;
        if (!(disc >= 0.0)) return false;
        for (const double t : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a})
            if (t > r.tmin && t < r.tmax) { h.t = float(t); return true; }
        return false;
    }
    vec3 normal(const vec3& p, const hit&) const override { return glm::normalize(p - c_); }
    aabb bounds() const override { return {c_ - vec3(r_), c_ + vec3(r_)}; }

private:
    vec3 c_;
    float r_;
};

trace_context context(int max_depth) { return trace_context{pcg32(7), max_depth, {}}; }

// The floor y = 0, diffuse with albedo 0.5, seen from (3, 1, 0) at the point (1, 0, 0).
const ray floor_ray{vec3(3, 1, 0), vec3(-2, -1, 0)};

// Radiance of a diffuse point p with normal n, lit by a point light: albedo / pi * I * cos / d^2.
float lambert(float albedo, float intensity, vec3 p, vec3 n, vec3 light) {
    const vec3 l = light - p;
    return albedo / pi * intensity * glm::dot(n, glm::normalize(l)) / glm::dot(l, l);
}

}  // namespace

TEST_CASE("01.4 Whitted shading: a lit diffuse plane has radiance albedo/pi I cos / d^2", "[ch01][pts:1]") {
    world w;
    const auto m = w.add(std::make_unique<diffuse>(color(0.5f, 0.25f, 0.125f)));
    w.add(std::make_unique<plane>(vec3(0, 1, 0), 0.0f, m));
    w.lights = {point_light{vec3(0, 2, 0), color(10.0f)}};
    trace_context ctx = context(3);
    const color c = trace(w, floor_ray, 0, ctx);
    const float expected = lambert(1.0f, 10.0f, vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 2, 0));
    CHECK(c.r == Approx(0.5f * expected).epsilon(1e-4));
    CHECK(c.g == Approx(0.25f * expected).epsilon(1e-4));
    CHECK(c.b == Approx(0.125f * expected).epsilon(1e-4));
    CHECK(ctx.counts.shadow == 1);
    CHECK(ctx.counts.reflection == 0);
    // Two lights add up; each costs one shadow ray.
    w.lights.push_back(point_light{vec3(4, 3, 1), color(2.0f, 0.0f, 5.0f)});
    trace_context ctx2 = context(3);
    const color c2 = trace(w, floor_ray, 0, ctx2);
    const float second = lambert(1.0f, 1.0f, vec3(1, 0, 0), vec3(0, 1, 0), vec3(4, 3, 1));
    CHECK(c2.r == Approx(0.5f * (expected + 2.0f * second)).epsilon(1e-4));
    CHECK(c2.g == Approx(0.25f * expected).epsilon(1e-4));
    CHECK(c2.b == Approx(0.125f * (expected + 5.0f * second)).epsilon(1e-4));
    CHECK(ctx2.counts.shadow == 2);
}

TEST_CASE("01.4 Whitted shading: shadowed points are black, misses see the background", "[ch01][pts:1]") {
    world w;
    const auto m = w.add(std::make_unique<diffuse>(color(0.5f)));
    w.add(std::make_unique<plane>(vec3(0, 1, 0), 0.0f, m));
    w.add(std::make_unique<test_ball>(vec3(0.5f, 1.0f, 0.0f), 0.2f, m));  // between (1, 0, 0) and the light
    w.lights = {point_light{vec3(0, 2, 0), color(10.0f)}};
    trace_context ctx = context(3);
    CHECK(trace(w, floor_ray, 0, ctx) == color(0.0f));  // no ambient term
    CHECK(ctx.counts.shadow == 1);
    // A point beside the shadow is lit again.
    const ray beside{vec3(-3, 1, 0), vec3(2, -1, 0)};  // hits (-1, 0, 0)
    CHECK(trace(w, beside, 0, ctx).r == Approx(lambert(0.5f, 10.0f, vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, 2, 0))));
    // A light below the floor does not light its top side.
    w.lights = {point_light{vec3(0, -2, 0), color(10.0f)}};
    CHECK(trace(w, beside, 0, ctx) == color(0.0f));
    // A miss returns the background.
    w.background = color(0.1f, 0.2f, 0.3f);
    CHECK(trace(w, ray{vec3(0, 1, 0), vec3(0, 1, 0)}, 0, ctx) == color(0.1f, 0.2f, 0.3f));
}

// A mirror floor y = 0 under a diffuse ceiling y = 4, a light at (0, 2, 0) between them. floor_ray hits
// the mirror at (1, 0, 0) and reflects to the ceiling at (-7, 4, 0).
TEST_CASE("01.4 Whitted shading: a mirror at the depth limit reflects nothing, below it the ceiling",
          "[ch01][pts:1]") {
    world w;
    const auto white = w.add(std::make_unique<diffuse>(color(0.5f)));
    const auto shiny = w.add(std::make_unique<mirror>(color(0.9f)));
    w.add(std::make_unique<plane>(vec3(0, 1, 0), 0.0f, shiny));
    w.add(std::make_unique<plane>(vec3(0, 1, 0), 4.0f, white));
    w.lights = {point_light{vec3(0, 2, 0), color(10.0f)}};
    trace_context at_limit = context(0);
    CHECK(trace(w, floor_ray, 0, at_limit) == color(0.0f));
    CHECK(at_limit.counts.reflection == 0);
    trace_context deeper = context(1);
    const color c = trace(w, floor_ray, 0, deeper);
    const float ceiling = lambert(0.5f, 10.0f, vec3(-7, 4, 0), vec3(0, -1, 0), vec3(0, 2, 0));
    CHECK(c.r == Approx(0.9f * ceiling).epsilon(1e-3));
    CHECK(deeper.counts.reflection == 1);
    // The same ray entering at depth 1 of a depth-1 limit is at the limit.
    trace_context limit_one = context(1);
    CHECK(trace(w, floor_ray, 1, limit_one) == color(0.0f));
}

// Two parallel mirrors y = 0 and y = 4: a ray bounces between them until the depth limit stops it.
TEST_CASE("01.4 Whitted shading: recursion stops exactly at the depth limit", "[ch01][pts:1]") {
    world w;
    const auto shiny = w.add(std::make_unique<mirror>(color(0.5f)));
    const auto white = w.add(std::make_unique<diffuse>(color(1.0f)));
    w.add(std::make_unique<plane>(vec3(0, 1, 0), 0.0f, shiny));
    w.add(std::make_unique<plane>(vec3(0, 1, 0), 4.0f, shiny));
    w.add(std::make_unique<plane>(vec3(1, 0, 0), -1000.0f, white));  // a far wall the last ray may reach
    for (const int limit : {0, 1, 2, 5, 9}) {
        trace_context ctx = context(limit);
        INFO("depth limit " << limit);
        CHECK(trace(w, ray{vec3(0, 2, 0), vec3(-1, 1, 0)}, 0, ctx) == color(0.0f));  // no lights: dark
        CHECK(ctx.counts.reflection == std::uint64_t(limit));
        CHECK(ctx.counts.shadow == 0);
        CHECK(ctx.counts.tests.values().rays == std::uint64_t(limit) + 1);
    }
}

TEST_CASE("01.4 Whitted shading: a rough mirror traces its S reflection rays per hit", "[ch01][pts:1]") {
    const float ceiling = lambert(0.5f, 10.0f, vec3(-7, 4, 0), vec3(0, -1, 0), vec3(0, 2, 0));
    for (const int samples : {1, 5, 16}) {
        for (const float roughness : {0.0f, 0.3f}) {
            world w;
            const auto white = w.add(std::make_unique<diffuse>(color(0.5f)));
            const auto rough = w.add(std::make_unique<rough_mirror>(color(0.9f), roughness, samples));
            w.add(std::make_unique<plane>(vec3(0, 1, 0), 0.0f, rough));
            w.add(std::make_unique<plane>(vec3(0, 1, 0), 4.0f, white));
            w.lights = {point_light{vec3(0, 2, 0), color(10.0f)}};
            INFO(samples << " samples, roughness " << roughness);
            trace_context ctx = context(1);
            const color c = trace(w, floor_ray, 0, ctx);
            CHECK(ctx.counts.reflection == std::uint64_t(samples));
            CHECK(ctx.counts.shadow == std::uint64_t(samples) + 1);  // the mirror hit and each ceiling hit
            if (roughness == 0.0f) CHECK(c.r == Approx(0.9f * ceiling).epsilon(1e-3));
            else CHECK((c.r > 0.0f && c.r < 0.9f * 0.5f / pi * 10.0f / 4.0f));
            trace_context flat = context(0);
            CHECK(trace(w, floor_ray, 0, flat) == color(0.0f));
            CHECK(flat.counts.reflection == 0);
        }
    }
}
