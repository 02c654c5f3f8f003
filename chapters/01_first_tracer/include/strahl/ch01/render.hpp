// Rendering an image: one primary ray per pixel centre, traced in parallel tiles. Each tile seeds its own
// pcg32 from (seed, tile index), so the image is bit-identical whatever the thread count or schedule.
#pragma once
#include "strahl/camera.hpp"
#include "strahl/ch01/whitted.hpp"
#include "strahl/image.hpp"
#include <string>
#include <vector>

namespace strahl::ch01 {

struct render_settings {
    int max_depth = 5;
    std::uint64_t seed = 1;
    int tile_size = 16;
    bool primary_only = false;  // closest hit only, shaded by the facing ratio (the sweep measures this)
    std::string progress_label;  // non-empty: draw a progress bar (when standard error is a terminal)
};

struct render_result {
    image img;
    std::vector<float> rays_per_pixel;  // every ray a pixel cost (primary, shadow, reflection), row-major
    ray_counts counts;
    double seconds = 0.0;
};

render_result render(const world& w, const camera& cam, const render_settings& settings);

}  // namespace strahl::ch01
