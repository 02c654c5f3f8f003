// The chapter's builders, each flattened by the SAH collapse, behind chapter 04's accel and walked by
// chapter 05's fast traversal.
#include "strahl/ch08/accel.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch08/atrbvh.hpp"
#include "strahl/ch08/hlbvh.hpp"
#include "strahl/ch08/ploc.hpp"
#include "strahl/ch08/treelet.hpp"

namespace strahl::ch08 {

std::vector<variant> variants() {
    std::vector<variant> list;
    list.push_back({"hlbvh", "HLBVH: Morton clusters of the codes' top 15 bits, an LBVH in each, the binned SAH over "
                             "the clusters (Pantaleoni and Luebke 2010; Garanzha et al. 2011)",
                    [](std::span<const aabb> b, std::span<const vec3> c) { return flatten(build_hlbvh(b, c)); }});
    for (const int radius : {1, 4, 16}) {
        ploc_params p;
        p.radius = radius;
        list.push_back({"ploc" + std::to_string(radius),
                        "PLOC: clusters in Morton order merged with their mutual nearest neighbour within " +
                            std::to_string(radius) + " places (Meister and Bittner 2018)",
                        [p](std::span<const aabb> b, std::span<const vec3> c) { return flatten(build_ploc(b, c, p)); }});
    }
    list.push_back({"trbvh", "TRBVH: chapter 07's LBVH, treelets of 7 leaves rebuilt optimally by dynamic programming, "
                             "3 rounds (Karras and Aila 2013)",
                    [](std::span<const aabb> b, std::span<const vec3> c) {
                        binary_tree t = lbvh_binary_tree(b, c);
                        restructure_trbvh(t);
                        return flatten(t);
                    }});
    list.push_back({"atrbvh", "ATRBVH: chapter 07's LBVH, treelets of 9 leaves rebuilt by agglomerative clustering, "
                              "2 rounds (Domingues and Pedrini 2015)",
                    [](std::span<const aabb> b, std::span<const vec3> c) {
                        binary_tree t = lbvh_binary_tree(b, c);
                        restructure_atrbvh(t);
                        return flatten(t);
                    }});
    return list;
}

std::unique_ptr<ch04::bvh_accel_base> make_accel(const variant& v) {
    return ch05::make_bvh_accel(false, "ch08-" + v.name + "-fast", v.build, ch05::walk_kind::fast);
}

}  // namespace strahl::ch08
