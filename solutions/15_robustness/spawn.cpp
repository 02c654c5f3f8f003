// Exercise 15.3 (the spawn offset, 3 points). Read: C. Waechter and N. Binder, "A fast and robust method
// for avoiding self-intersection", Ray Tracing Gems, chapter 6, 2019.
#include "strahl/ch15/spawn.hpp"
#include <bit>
#include <cmath>
#include <cstdint>

namespace strahl::ch15 {

vec3 offset_integer(const vec3& p, const vec3& n, const vec3& w) {
    constexpr float origin = 1.0f / 32.0f, float_scale = 1.0f / 65536.0f, int_scale = 256.0f;
    const vec3 nf = facing(n, w);
    vec3 out;
    for (int i = 0; i < 3; ++i) {
        if (std::fabs(p[i]) < origin) {
            out[i] = p[i] + float_scale * nf[i];  // near the origin: a small float offset
            continue;
        }
        // Elsewhere: move p's bits by int(256 n) ulps, away from zero where n points away from zero.
        const std::int32_t ulps = std::int32_t(int_scale * nf[i]);
        const std::uint32_t bits = std::bit_cast<std::uint32_t>(p[i]);
        const std::uint32_t moved = p[i] < 0.0f ? bits - std::uint32_t(ulps) : bits + std::uint32_t(ulps);
        out[i] = std::bit_cast<float>(moved);
    }
    return out;
}

}  // namespace strahl::ch15
