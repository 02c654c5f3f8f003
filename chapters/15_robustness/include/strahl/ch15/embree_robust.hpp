// Embree 3 on chapter 15's escape test: its own BVH and triangle test, with its default scene flags and with
// RTC_SCENE_FLAG_ROBUST ("avoid optimizations that reduce arithmetic accuracy"), on the same rays. Compiled
// with Embree where CMake found it (STRAHL_HAVE_EMBREE); elsewhere embree_available() is false and
// embree_found throws.
#pragma once
#include "strahl/ray.hpp"
#include "strahl/scene.hpp"
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace strahl::ch15 {

bool embree_available();
std::string embree_version();  // "3.13.5", or "not available"

// Which rays hit the mesh (1) or nothing (0) in Embree (rtcIntersect1, flush-to-zero and denormals-are-zero
// set as Embree asks), traced in chunks on TBB's threads; robust sets RTC_SCENE_FLAG_ROBUST.
std::vector<std::uint8_t> embree_found(const triangle_mesh& m, std::span<const ray> rays, bool robust);

}  // namespace strahl::ch15
