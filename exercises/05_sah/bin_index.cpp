// Exercise 05.2 bin assignment (5 points). Read: I. Wald, "On fast construction of SAH-based bounding
// volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2007, section 3.
#include "strahl/ch05/sah.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch05 {

// Goal: the bin of centroid coordinate c: int(m.scale * (c - m.lo)), clamped to [0, m.k - 1]; a NaN goes to
// bin 0.
// Hint: clamp the float, then convert it, never the other way round.
// Why: why can a centroid inside [lo, hi] land in bin k, and why is converting first and clamping afterwards
// undefined behaviour rather than merely wrong?
// Step by step: HINTS.md, 05.2.
int bin_index(const bin_mapping& m, float c) {
    STRAHL_TODO("05.2 bin assignment");
}

}  // namespace strahl::ch05
