// Parallel loops on TBB's thread pool. The course never writes its own thread pool.
#pragma once
#include <algorithm>
#include <memory>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

namespace strahl {

// An image tile: pixels [x0, x1) x [y0, y1), and its index in scanline order of tiles (for seeding RNGs
// deterministically, whatever thread runs it).
struct tile {
    int x0, y0, x1, y1;
    int index;
};

// Calls f(tile) for every tile of a width x height image, in parallel. Tiles are tile_size square
// (smaller at the right and bottom edges).
template <class F>
void parallel_for_tiles(int width, int height, int tile_size, F&& f) {
    const int tiles_x = (width + tile_size - 1) / tile_size;
    const int tiles_y = (height + tile_size - 1) / tile_size;
    tbb::parallel_for(tbb::blocked_range<int>(0, tiles_x * tiles_y, 1), [&](const tbb::blocked_range<int>& r) {
        for (int i = r.begin(); i != r.end(); ++i) {
            const int tx = i % tiles_x, ty = i / tiles_x;
            const tile t{tx * tile_size, ty * tile_size, std::min(width, (tx + 1) * tile_size),
                         std::min(height, (ty + 1) * tile_size), i};
            f(t);
        }
    });
}

// Calls f(begin, end) on chunks of [0, n) in parallel.
template <class F>
void parallel_for_chunks(std::size_t n, std::size_t grain, F&& f) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, std::max<std::size_t>(1, grain)),
                      [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
}

// Limits TBB to n threads while alive (n <= 0: no limit, TBB's default of one per core).
class thread_limit {
public:
    explicit thread_limit(int n) {
        if (n > 0) control_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, n);
    }

private:
    std::unique_ptr<tbb::global_control> control_;
};

}  // namespace strahl
