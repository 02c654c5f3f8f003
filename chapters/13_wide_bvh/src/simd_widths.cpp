// What chapter 13's programs print about the SIMD widths of this build.
#include "strahl/ch13/accel.hpp"
#include "strahl/simd.hpp"

namespace strahl::ch13 {

std::string simd_widths() {
    std::string s;
    s += std::string("4: ") + (simd::native<4> ? "intrinsics" : "scalar fallback");
    s += std::string(", 8: ") + (simd::native<8> ? "intrinsics" : "scalar fallback");
    s += std::string(", 16: ") + (simd::native<16> ? "intrinsics" : "scalar fallback");
    return s;
}

}  // namespace strahl::ch13
