// Math vocabulary of the course: GLM vectors under short names, and the few helpers every chapter uses.
#pragma once
#include <glm/glm.hpp>
#include <cmath>
#include <cstdint>
#include <iosfwd>
#include <limits>

namespace strahl {

using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec3 = glm::uvec3;
using mat4 = glm::mat4;
using color = glm::vec3;  // linear RGB radiance

inline constexpr float pi = 3.14159265358979323846f;
inline constexpr float inf = std::numeric_limits<float>::infinity();

// True when all three components are finite (no NaN, no Inf).
inline bool is_finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Index (0, 1, 2) of the largest component.
inline int max_axis(const vec3& v) { return v.x >= v.y ? (v.x >= v.z ? 0 : 2) : (v.y >= v.z ? 1 : 2); }

// Mirror reflection of the incoming direction d about the normal n (both need not be normalised for n).
inline vec3 reflect(const vec3& d, const vec3& n) { return d - 2.0f * glm::dot(d, n) * n; }

}  // namespace strahl

namespace glm {
// Vectors print as "(x, y, z)", floats with 9 digits (every digit that tells two floats apart): for test
// failures (Catch2 finds these by argument-dependent lookup) and logs. common/src/math.cpp.
std::ostream& operator<<(std::ostream& os, const vec2& v);
std::ostream& operator<<(std::ostream& os, const vec3& v);
std::ostream& operator<<(std::ostream& os, const ivec3& v);
std::ostream& operator<<(std::ostream& os, const uvec3& v);
}  // namespace glm
