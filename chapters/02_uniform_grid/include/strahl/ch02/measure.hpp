// What chapter 02's program measures: primary rays through any structure, timed (median of runs) and
// counted, and a simple facing-ratio picture of the hits.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/camera.hpp"
#include "strahl/image.hpp"
#include <span>
#include <string>
#include <vector>

namespace strahl::ch02 {

std::vector<ray> primary_rays(const camera& cam);

struct trace_result {
    double seconds = 0.0;       // median over the runs
    double mrays = 0.0;         // million rays per second
    counter_values counts;      // from one counted run
    std::vector<hit> hits;
};

// Traces rays with a.intersect in parallel chunks, `runs` times, and once more counted.
trace_result trace(const accel& a, std::span<const ray> rays, int runs, const std::string& progress_label = {});

// Grey by the facing ratio |cos| between ray and triangle normal; misses dark blue.
image facing_image(const triangle_mesh& mesh, const camera& cam, std::span<const ray> rays, std::span<const hit> hits);

// Per pixel, the primitive tests its primary ray cost (for a heat map).
std::vector<float> tests_per_pixel(const accel& a, std::span<const ray> rays);

}  // namespace strahl::ch02
