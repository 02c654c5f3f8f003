// Primary rays of a camera through any structure, as the chapters' programs measure them: an untimed
// warm-up over every 8th row, one timed run without counters on all threads (with a progress bar), then a
// counting run that keeps each pixel's counts (for heat maps) and their sum (for tests per ray).
#pragma once
#include "strahl/accel.hpp"
#include "strahl/camera.hpp"
#include <string>
#include <vector>

namespace strahl {

struct primary_trace {
    std::vector<hit> hits;       // per pixel, scanline order, row 0 at the top
    double seconds = 0.0;        // the timed run
    counter_values counts;       // summed over all pixels (zero where the structure cannot count)
    std::vector<float> box_tests, prim_tests;  // per pixel, from the counting run
};

primary_trace trace_primary(const accel& a, const camera& cam, const std::string& label);

}  // namespace strahl
