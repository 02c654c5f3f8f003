// Names of chapter 14's hybrid tracers.
#include "strahl/ch14/accel.hpp"
#include <string>

namespace strahl::ch14 {

std::string threshold_name(int threshold) {
    return threshold == automatic ? std::string("auto") : std::to_string(threshold);
}

std::string describe(const hybrid_config& c) {
    const std::string strict = std::string(c.strict ? "; strict boxes, tested from tmin (not exact)" : "") +
                               (c.order == ch13::child_order::collapsed ? "; any hit in stored order" : "") +
                               (c.octant_order ? "; lone rays in the octant's order" : "");
    const std::string s = "hybrid, " + std::to_string(c.lanes) + " lanes, " + std::to_string(c.tile_w) + "x" +
                          std::to_string(c.tile_h) + " tiles, ";
    if (c.threshold == automatic) return s + "threshold per packet from its coherence" + strict;
    if (c.threshold == 0) return s + "rays never leave the packet" + strict;
    if (c.threshold == c.lanes) return s + "every ray alone from the root" + strict;
    return s + "rays leave at <= " + std::to_string(c.threshold) + " active lanes" + strict;
}

}  // namespace strahl::ch14
