// strahl/parallel.hpp's loops over TBB.
#include "strahl/parallel.hpp"
#include <algorithm>
#include <sched.h>
#include <stdexcept>
#include <string>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

namespace strahl {

void parallel_for_tiles(int width, int height, int tile_size, const std::function<void(const tile&)>& f) {
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

void parallel_for_chunks(std::size_t n, std::size_t grain, const std::function<void(std::size_t, std::size_t)>& f) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, std::max<std::size_t>(1, grain)),
                      [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
}

void parallel_invoke(const std::function<void()>& a, const std::function<void()>& b) { tbb::parallel_invoke(a, b); }

int parallel_threads() {
    const auto limit = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
    return int(std::max<std::size_t>(1, std::min<std::size_t>(limit, std::size_t(tbb::this_task_arena::max_concurrency()))));
}

struct thread_limit::control {
    tbb::global_control limit;
};

thread_limit::thread_limit(int n) {
    if (n > 0) control_.reset(new control{tbb::global_control(tbb::global_control::max_allowed_parallelism, n)});
}

thread_limit::~thread_limit() = default;

struct pinned_thread::saved {
    cpu_set_t before;
};

pinned_thread::pinned_thread(int cpu) {
    if (cpu < 0) return;
    if (!cpu_allowed(cpu)) throw std::invalid_argument("CPU " + std::to_string(cpu) + " is not one this process may run on");
    auto s = std::make_unique<saved>();
    if (sched_getaffinity(0, sizeof s->before, &s->before) != 0) return;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpu, &one);
    if (sched_setaffinity(0, sizeof one, &one) == 0) saved_ = std::move(s);
}

pinned_thread::~pinned_thread() {
    if (saved_) sched_setaffinity(0, sizeof saved_->before, &saved_->before);
}

int first_allowed_cpu() {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) != 0) return 0;
    for (int c = 0; c < CPU_SETSIZE; ++c)
        if (CPU_ISSET(c, &set)) return c;
    return 0;
}

bool cpu_allowed(int cpu) {
    if (cpu < 0 || cpu >= CPU_SETSIZE) return false;
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) != 0) return false;
    return CPU_ISSET(cpu, &set);
}

}  // namespace strahl
