// Exercise 05.2 bin assignment. I. Wald, "On fast construction of SAH-based bounding volume hierarchies",
// IEEE Symposium on Interactive Ray Tracing 2007, section 3 (k bins of equal width over the centroid box).
#include "strahl/ch05/sah.hpp"

namespace strahl::ch05 {

int bin_index(const bin_mapping& m, float c) {
    const float f = m.scale * (c - m.lo);
    // The clamp, in float before the conversion: the top (c == hi gives k) and beyond; below lo; NaN.
    if (f >= float(m.k - 1)) return m.k - 1;
    if (!(f > 0.0f)) return 0;
    return int(f);
}

}  // namespace strahl::ch05
