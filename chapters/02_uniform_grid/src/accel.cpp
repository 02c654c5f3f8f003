// The race's entry to chapter 02: the uniform grid over triangles or over chapter 01's virtual objects.
#include "strahl/ch02/accel.hpp"

namespace strahl::ch02 {

std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives, const grid_options& opt) {
    if (virtual_primitives) return std::make_unique<grid_accel<ch01::object_set>>(opt);
    return std::make_unique<grid_accel<ch01::triangle_set>>(opt);
}

std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives) { return make_accel(virtual_primitives, {}); }

}  // namespace strahl::ch02
