// Exercise 11.3 the type-sorted leaf (3 points). Read: I. Wald, "Realtime Ray Tracing and Interactive
// Global Illumination", PhD thesis, 2004, section 7.1.
#include "strahl/ch11/type_sorted.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch11 {

// Append the leaf's triangles, spheres and planes to out's arrays (out.triangles, out.spheres, out.planes
// and their ids in out.ids[0], [1], [2]), each type in the leaf's order, and return where each type's run
// starts and how many it holds. shapes[id].index() is the type: 0 triangle, 1 sphere, 2 plane.
// Hint: an empty run still has a first: the array's size at the time.
// Why: the leaf test never loops over an empty run; why give it a first all the same, and why the array's size
// then rather than 0: what must every [first, first + count) say about the runs, leaf after leaf in the tree's order?
sorted_leaf sort_leaf_by_type(std::span<const std::uint32_t> leaf, std::span<const shape> shapes,
                              sorted_primitives& out) {
    STRAHL_TODO("11.3 the type-sorted leaf");
}

}  // namespace strahl::ch11
