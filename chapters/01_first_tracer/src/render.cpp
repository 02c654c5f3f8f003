// Rendering in parallel tiles with deterministic per-tile random numbers, counting rays by kind.
#include "strahl/ch01/render.hpp"
#include "strahl/parallel.hpp"
#include "strahl/progress.hpp"
#include "strahl/timer.hpp"
#include <memory>
#include <mutex>

namespace strahl::ch01 {

namespace {
// Primary visibility only: the closest hit, grey by the facing ratio |cos| (no lights, no recursion).
color shade_primary(const world& w, const ray& r, trace_context& ctx) {
    surface s;
    if (!w.closest_hit(r, s, ctx.counts.tests)) return w.background;
    return color(0.9f * glm::dot(s.n, -glm::normalize(r.dir)));
}
}  // namespace

render_result render(const world& w, const camera& cam, const render_settings& settings) {
    const int width = cam.width(), height = cam.height();
    render_result out;
    out.img = image(width, height);
    out.rays_per_pixel.assign(std::size_t(width) * height, 0.0f);
    std::unique_ptr<progress_bar> bar;
    if (!settings.progress_label.empty())
        bar = std::make_unique<progress_bar>(settings.progress_label, std::uint64_t(width) * height, "px");
    std::mutex merge;
    const timer clock;
    parallel_for_tiles(width, height, settings.tile_size, [&](const tile& t) {
        // One context per tile, seeded by the tile's index: the same numbers whichever thread runs it.
        trace_context ctx{pcg32(settings.seed, std::uint64_t(t.index)), settings.max_depth, {}};
        for (int y = t.y0; y < t.y1; ++y) {
            for (int x = t.x0; x < t.x1; ++x) {
                const ray r = primary_ray(cam, float(x) + 0.5f, float(y) + 0.5f);
                const std::uint64_t before = ctx.counts.total();
                ++ctx.counts.primary;
                out.img.at(x, y) = settings.primary_only ? shade_primary(w, r, ctx) : trace(w, r, 0, ctx);
                out.rays_per_pixel[std::size_t(y) * width + x] = float(ctx.counts.total() - before);
            }
        }
        if (bar) bar->add(std::uint64_t(t.x1 - t.x0) * std::uint64_t(t.y1 - t.y0));
        const std::lock_guard lock(merge);
        out.counts.merge(ctx.counts);  // integer sums: the same totals in any order
    });
    out.seconds = clock.seconds();
    if (bar) bar->finish();
    return out;
}

}  // namespace strahl::ch01
