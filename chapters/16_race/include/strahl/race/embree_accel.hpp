// Embree 3 (Wald et al., "Embree: A Kernel Framework for Efficient CPU Ray Tracing", SIGGRAPH 2014) behind
// the course's accel interface: the baseline every chapter is measured against, and an independent oracle.
// Embree has its own triangle test, so its answers may differ from brute force on a handful of edge cases:
// exact() is false and the race counts the differences instead of demanding none.
#pragma once
#include "strahl/accel.hpp"
#include <memory>

namespace strahl::race {

struct embree_config {
    enum class quality { medium, high } build_quality = quality::medium;
    // Trace primary rays with rtcIntersect8 on 4x2 pixel tiles of an image this wide (rays in scanline
    // order, as the race writes them); 0 traces one ray at a time with rtcIntersect1 / rtcOccluded1.
    int packet_image_width = 0;
    int threads = 1;  // Embree's own build threads
};

// Whether this build found Embree 3 (find_package(embree 3)).
bool embree_available();

// Throws std::runtime_error where Embree is not available.
std::unique_ptr<accel> make_embree_accel(const embree_config& config);

}  // namespace strahl::race
