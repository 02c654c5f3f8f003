// Exercise 01.1 camera ray (4 points). Only primary_ray and the common camera are used here.
#include "strahl/ch01/whitted.hpp"
#include <catch2/catch.hpp>
#include <vector>

using namespace strahl;

namespace {
std::vector<camera> test_cameras() {
    return {camera(camera_desc{vec3(0, 0, 5), vec3(0), vec3(0, 1, 0), 45.0f}, 64, 48),
            camera(camera_desc{vec3(3, -2, 7), vec3(0.5f, 1, -1), vec3(0, 1, 0), 70.0f}, 100, 300),
            camera(camera_desc{vec3(-1, 4, 2), vec3(0), vec3(0.3f, 0.2f, 1), 20.0f}, 640, 480)};
}
}  // namespace

TEST_CASE("01.1 camera ray: equals camera::generate at centres, corners and in between", "[ch01][pts:2]") {
    for (const camera& cam : test_cameras()) {
        const float w = float(cam.width()), h = float(cam.height());
        for (const vec2 xy : {vec2(0.5f), vec2(0.0f), vec2(w, h), vec2(w, 0.0f), vec2(0.0f, h), vec2(w / 2, h / 2),
                              vec2(w * 0.3f, h * 0.8f), vec2(17.5f, 3.5f)}) {
            const ray mine = ch01::primary_ray(cam, xy.x, xy.y);
            const ray ref = cam.generate(xy.x, xy.y);
            INFO("camera " << cam.width() << "x" << cam.height() << " at (" << xy.x << ", " << xy.y << ")");
            CHECK(mine.org == ref.org);
            CHECK(glm::length(mine.dir - ref.dir) < 1e-6f);
            CHECK(mine.tmin == 0.0f);
            CHECK(mine.tmax == inf);
        }
    }
}

TEST_CASE("01.1 camera ray: row 0 is on top, column 0 on the left, the field of view is vertical",
          "[ch01][pts:2]") {
    for (const camera& cam : test_cameras()) {
        INFO("camera " << cam.width() << "x" << cam.height() << ", vertical field of view "
                       << cam.desc().vfov_degrees << " degrees");
        const float w = float(cam.width()), h = float(cam.height());
        const ray centre = ch01::primary_ray(cam, w / 2, h / 2);
        CHECK(glm::length(centre.dir - cam.forward()) < 1e-6f);
        const ray top_left = ch01::primary_ray(cam, 0.5f, 0.5f);
        CHECK(std::abs(glm::length(top_left.dir) - 1.0f) < 1e-6f);
        CHECK(glm::dot(top_left.dir, cam.up()) > 0.0f);
        CHECK(glm::dot(top_left.dir, cam.right()) < 0.0f);
        // The top edge's middle is half the vertical field of view above the view direction; the right
        // edge's middle is atan(aspect tan(fov / 2)) to the right.
        const float half_fov = glm::radians(cam.desc().vfov_degrees) / 2;
        const ray top = ch01::primary_ray(cam, w / 2, 0.0f);
        CHECK(std::acos(std::min(1.0f, glm::dot(top.dir, cam.forward()))) == Approx(half_fov).epsilon(1e-4));
        const ray right = ch01::primary_ray(cam, w, h / 2);
        CHECK(glm::dot(right.dir, cam.right()) > 0.0f);
        CHECK(std::atan(glm::dot(right.dir, cam.right()) / glm::dot(right.dir, cam.forward())) ==
              Approx(std::atan(cam.aspect() * std::tan(half_fov))).epsilon(1e-4));
    }
}
