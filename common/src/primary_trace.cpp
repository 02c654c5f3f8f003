#include "strahl/primary_trace.hpp"
#include "strahl/parallel.hpp"
#include "strahl/progress.hpp"
#include "strahl/timer.hpp"
#include <mutex>

namespace strahl {

primary_trace trace_primary(const accel& a, const camera& cam, const std::string& label) {
    const int w = cam.width(), h = cam.height();
    std::vector<ray> rays(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) rays[std::size_t(y) * w + x] = cam.pixel_ray(x, y);
    primary_trace run;
    run.hits.resize(rays.size());
    run.box_tests.resize(rays.size());
    run.prim_tests.resize(rays.size());
    // A warm-up over every 8th row, untimed: it starts the worker threads and brings the structure into
    // the caches, so that the first structure a program measures is not charged for either.
    parallel_for_chunks(std::size_t(h + 7) / 8, 1, [&](std::size_t r0, std::size_t r1) {
        for (std::size_t y = r0 * 8; y < r1 * 8 && y < std::size_t(h); y += 8)
            a.intersect(std::span(rays).subspan(y * w, w), std::span(run.hits).subspan(y * w, w));
    });
    {
        progress_bar bar(label, std::uint64_t(h), "rows");
        const timer clock;
        parallel_for_chunks(std::size_t(h), 4, [&](std::size_t y0, std::size_t y1) {
            const std::size_t b = y0 * w, n = (y1 - y0) * w;
            a.intersect(std::span(rays).subspan(b, n), std::span(run.hits).subspan(b, n));
            bar.add(y1 - y0);
        });
        run.seconds = clock.seconds();
        bar.finish();
    }
    // The counting run, one ray at a time so that each pixel keeps its own counts.
    std::mutex m;
    std::vector<hit> counted(rays.size());
    parallel_for_chunks(std::size_t(h), 4, [&](std::size_t y0, std::size_t y1) {
        counter_values sum;
        for (std::size_t i = y0 * w; i < y1 * w; ++i) {
            const auto c = a.intersect_counted(std::span(rays).subspan(i, 1), std::span(counted).subspan(i, 1));
            if (!c) continue;
            run.box_tests[i] = float(c->box_tests);
            run.prim_tests[i] = float(c->prim_tests);
            sum += *c;
        }
        const std::lock_guard lock(m);
        run.counts += sum;
    });
    return run;
}

}  // namespace strahl
