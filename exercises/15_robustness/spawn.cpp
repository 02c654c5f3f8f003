// Exercise 15.3 (the spawn offset, 3 points). Read: C. Waechter and N. Binder, "A fast and robust method
// for avoiding self-intersection", Ray Tracing Gems, chapter 6, 2019.
#include "strahl/ch15/spawn.hpp"
#include "strahl/todo.hpp"
#include <bit>
#include <cmath>
#include <cstdint>

namespace strahl::ch15 {

// Exercise 15.3: spawn.hpp gives the rule per axis. Hint: std::bit_cast<std::uint32_t>(x) gives x's bits;
// do the integer arithmetic unsigned (it wraps, where signed overflow would be undefined).
// Why: why move p by a number of ulps rather than by a fixed distance: how does the offset then grow with |p|, and
// why does it fail below 1/32, where the rule adds 2^-16 n' instead?
vec3 offset_integer(const vec3& p, const vec3& n, const vec3& w) {
    STRAHL_TODO("15.3 the spawn offset");
}

}  // namespace strahl::ch15
