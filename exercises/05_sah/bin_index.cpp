// Exercise 05.2 bin assignment (5 points). Read: I. Wald, "On fast construction of SAH-based bounding
// volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2007, section 3.
#include "strahl/ch05/sah.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch05 {

// The bin of centroid coordinate c: int(m.scale * (c - m.lo)), clamped to [0, m.k - 1].
//   compute f = m.scale * (c - m.lo) as a float;
//   clamp f first (c == hi gives exactly k; rounding can give k just below hi; NaN goes to bin 0),
//   then convert: converting a float outside int's range or a NaN is undefined behaviour.
int bin_index(const bin_mapping& m, float c) {
    STRAHL_TODO("05.2 bin assignment");
}

}  // namespace strahl::ch05
