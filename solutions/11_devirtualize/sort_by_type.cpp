// Exercise 11.3 the type-sorted leaf (3 points). Read: I. Wald, "Realtime Ray Tracing and Interactive
// Global Illumination", PhD thesis, 2004, section 7.1.
#include "strahl/ch11/type_sorted.hpp"

namespace strahl::ch11 {

sorted_leaf sort_leaf_by_type(std::span<const std::uint32_t> leaf, std::span<const shape> shapes,
                              sorted_primitives& out) {
    sorted_leaf l;
    for (int type = 0; type < shape_types; ++type) {
        // Each type's range starts at its array's end; one pass over the leaf per type keeps the order.
        l.first[type] = std::uint32_t(out.ids[type].size());
        for (const std::uint32_t id : leaf) {
            const shape& s = shapes[id];
            if (int(s.index()) != type) continue;
            if (type == 0) out.triangles.push_back(std::get<triangle_shape>(s));
            if (type == 1) out.spheres.push_back(std::get<sphere_shape>(s));
            if (type == 2) out.planes.push_back(std::get<plane_shape>(s));
            out.ids[type].push_back(id);
        }
        l.count[type] = std::uint32_t(out.ids[type].size()) - l.first[type];
    }
    return l;
}

}  // namespace strahl::ch11
