// The scenes on which chapters 07 and 08 compare their builders: the teapot in a stadium (where 30-bit codes
// run out), a random soup of 200,000 triangles, the bunny and Sponza (where the shared meshes are); --quick
// takes the teapot and a soup of 20,000.
#pragma once
#include "strahl/scene.hpp"
#include <string>
#include <vector>

namespace strahl::ch07 {

// --scene NAME, checked before any work: "quick" with --quick, else stadium, soup, bunny, sponza, teapot or
// all; throws usage_error naming the choices otherwise.
std::string builder_scene_choice(const std::string& scene_option, bool quick);

// The scenes that choice names, in the order above (a shared mesh that is not there is left out, said).
std::vector<scene> builder_scenes(const std::string& choice);

}  // namespace strahl::ch07
