// Exercise 05.3 prefix and suffix sweeps over bins (10 points). Read: I. Wald, "On fast construction of
// SAH-based bounding volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2007, section 3.
#include "strahl/ch05/sah.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch05 {

// The boundary b (bins [0, b) left, [b, k) right) with the lowest SAH cost, in two linear sweeps:
//   fewer than 2 bins: no boundary, return bin_split{} (index 0, cost +inf);
//   suffix sweep, b = k-1 down to 1: grow a box by bins[b].box, right_area[b] = its surface_area();
//   prefix sweep, b = 1 up to k-1: grow a box by bins[b-1].box and count N_L (N_R = total - N_L);
//     skip b if N_L == 0 or N_R == 0;
//     cost = C_T + C_I * (A(L) * N_L + A(R) * N_R) / area_parent, exercise 05.1's formula (written out
//     here, not called: each exercise is graded on its own);
//     keep it if strictly lower than the best so far (so the lowest index wins a tie).
bin_split best_boundary(std::span<const bin> bins, std::span<float> right_area, const sah_costs& c,
                        float area_parent) {
    STRAHL_TODO("05.3 prefix and suffix sweeps");
}

}  // namespace strahl::ch05
