// Exercise 08.1 forming a treelet (8 points). Read: treelet.hpp; T. Karras and T. Aila, "Fast parallel
// construction of high-quality bounding volume hierarchies", HPG 2013, section 4.1.
#include "strahl/ch08/treelet.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch08 {

// Goal: the treelet of `root`: a leaf of t gives leaves {root} and no inner node; otherwise start from
// inner {root}, leaves {left child, right child}, and while there are fewer than n_leaves leaves, expand
// the treelet leaf of largest surface area that is an inner node of t (equal areas: the lower node index):
// remove it from `leaves`, append its left then its right child to `leaves`, append it to `inner`. Stop
// early when every treelet leaf holds a single primitive.
// Hint: a linear scan over the (at most 16) leaves finds the largest; skip the leaves of t.
// Why: why expand the largest leaf first: which nodes does the SAH weigh most, and what could the DP do
// with a treelet whose leaves are tiny?
// Step by step: HINTS.md, 08.1.
treelet form_treelet(const binary_tree& t, std::uint32_t root, int n_leaves) {
    STRAHL_TODO("08.1 forming a treelet");
}

}  // namespace strahl::ch08
