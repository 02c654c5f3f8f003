// Names and figures of chapter 12's packet tracers.
#include "strahl/ch12/accel.hpp"
#include <string>

namespace strahl::ch12 {

const char* to_string(walk_kind w) {
    switch (w) {
    case walk_kind::masked: return "masked";
    case walk_kind::ranged: return "ranged";
    case walk_kind::partition: return "partition";
    case walk_kind::wide: return "wide";
    case walk_kind::frustum: return "frustum";
    }
    return "?";
}

std::string describe(const packet_config& c) {
    return std::string(to_string(c.walk)) + " walk, " + std::to_string(c.lanes) + " lanes, " + std::to_string(c.tile_w) +
           "x" + std::to_string(c.tile_h) + " tiles";
}

double lane_stats::mean_active() const {
    double sum = 0, n = 0;
    for (std::size_t k = 0; k < visits.size(); ++k) sum += double(k) * double(visits[k]), n += double(visits[k]);
    return n > 0 ? sum / n : 0.0;
}

}  // namespace strahl::ch12
