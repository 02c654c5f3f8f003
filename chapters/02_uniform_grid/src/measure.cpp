// Measuring a structure on primary rays: time (median of runs, the machines are shared), counters, pictures.
#include "strahl/ch02/measure.hpp"
#include "strahl/parallel.hpp"
#include "strahl/progress.hpp"
#include "strahl/timer.hpp"
#include <cmath>

namespace strahl::ch02 {

std::vector<ray> primary_rays(const camera& cam) {
    std::vector<ray> rays;
    rays.reserve(std::size_t(cam.width()) * std::size_t(cam.height()));
    for (int y = 0; y < cam.height(); ++y)
        for (int x = 0; x < cam.width(); ++x) rays.push_back(cam.pixel_ray(x, y));
    return rays;
}

trace_result trace(const accel& a, std::span<const ray> rays, int runs, const std::string& progress_label) {
    trace_result out;
    out.hits.resize(rays.size());
    constexpr std::size_t chunk = 1024;
    std::vector<double> seconds;
    progress_bar bar(progress_label.empty() ? "trace" : progress_label, std::uint64_t(runs + 1) * rays.size(), "rays");
    if (progress_label.empty()) bar.set_drawing(false);
    for (int k = -1; k < runs; ++k) {  // run -1 warms the caches up, untimed
        const timer t;
        parallel_for_chunks(rays.size(), chunk, [&](std::size_t b, std::size_t e) {
            a.intersect(rays.subspan(b, e - b), std::span<hit>(out.hits).subspan(b, e - b));
            bar.add(e - b);
        });
        if (k >= 0) seconds.push_back(t.seconds());
    }
    bar.finish();
    out.seconds = median(seconds);
    out.mrays = double(rays.size()) / std::max(out.seconds, 1e-9) * 1e-6;
    std::vector<hit> counted(rays.size());
    if (auto c = a.intersect_counted(rays, counted)) out.counts = *c;
    return out;
}

image facing_image(const triangle_mesh& mesh, const camera& cam, std::span<const ray> rays, std::span<const hit> hits) {
    image img(cam.width(), cam.height(), color(0.05f, 0.07f, 0.15f));
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (!hits[i].found()) continue;
        const auto v = mesh.triangle(hits[i].prim);
        const vec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
        const float len = glm::length(n) * glm::length(rays[i].dir);
        const float f = len > 0.0f ? std::abs(glm::dot(n, rays[i].dir)) / len : 0.0f;
        img.pixels[i] = color(0.15f + 0.85f * f);
    }
    return img;
}

std::vector<float> tests_per_pixel(const accel& a, std::span<const ray> rays) {
    std::vector<float> tests(rays.size());
    parallel_for_chunks(rays.size(), 256, [&](std::size_t b, std::size_t e) {
        hit h;
        for (std::size_t i = b; i < e; ++i)
            if (auto c = a.intersect_counted(rays.subspan(i, 1), std::span<hit>(&h, 1))) tests[i] = float(c->prim_tests);
    });
    return tests;
}

}  // namespace strahl::ch02
