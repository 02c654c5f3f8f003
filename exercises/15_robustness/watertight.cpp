// Exercises 15.1 (the permutation and the shear, 3 points) and 15.2 (the edge functions with the double
// fallback, 5 points). Read: S. Woop, C. Benthin and I. Wald, "Watertight ray/triangle intersection",
// JCGT 2(1), 2013, sections 3 and 4 (its figure 7 is the whole test).
#include "strahl/ch15/watertight.hpp"
#include "strahl/todo.hpp"
#include <cmath>
#include <utility>

namespace strahl::ch15 {

// Exercise 15.1: the axis of the largest |dir| (x before y before z on ties), the other two after it
// (swapped when dir[kz] < 0), and the three shear factors. watertight.hpp says exactly what each is.
// Why: why must kz be the axis of the largest |dir|: what would sx = dir[kx] / dir[kz] and sz = 1 / dir[kz] do to
// the sheared vertices if dir[kz] were the smallest component, or 0?
shear make_shear(const vec3& dir) {
    STRAHL_TODO("15.1 the permutation and the shear");
}

// Exercise 15.2: steps a to e of watertight.hpp, in that order, with those operations (the tests compare
// t, u and v bit for bit with the reference). Hint: double(x) * double(y) of two floats is exact.
// Why: can a float edge function Cx By - Cy Bx come out with the wrong sign, or only 0 where the exact value is not?
// Why is the recompute in double then needed only at exactly 0, and what does it decide there?
bool intersect_watertight(const ray& r, const shear& s, const vec3& v0, const vec3& v1, const vec3& v2, float& t,
                          float& u, float& v) {
    STRAHL_TODO("15.2 the edge functions with the double fallback");
}

}  // namespace strahl::ch15
