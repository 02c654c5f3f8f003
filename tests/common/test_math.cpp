// strahl/math.hpp's printing of GLM vectors, as test failures show them.
#include "strahl/math.hpp"
#include <catch2/catch.hpp>

using namespace strahl;

TEST_CASE("GLM vectors print in test failures, floats with 9 digits", "[common][math]") {
    CHECK(Catch::Detail::stringify(vec3(1.0f, 0.1f, -2.0f)) == "(1, 0.100000001, -2)");
    CHECK(Catch::Detail::stringify(glm::ivec3(3, -4, 5)) == "(3, -4, 5)");
    CHECK(Catch::Detail::stringify(vec2(0.5f, 1e-7f)) == "(0.5, 1.00000001e-07)");
}
