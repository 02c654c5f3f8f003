// Parallel loops on TBB's thread pool. The course never writes its own thread pool.
// The loops take a std::function and run in common/src/parallel.cpp, so that only that file parses TBB's
// headers (2.4 s a file here); one indirect call per tile or chunk costs nothing beside the work in it.
#pragma once
#include <cstddef>
#include <functional>
#include <memory>

namespace strahl {

// An image tile: pixels [x0, x1) x [y0, y1), and its index in scanline order of tiles (for seeding RNGs
// deterministically, whatever thread runs it).
struct tile {
    int x0, y0, x1, y1;
    int index;
};

// Calls f(tile) for every tile of a width x height image, in parallel. Tiles are tile_size square
// (smaller at the right and bottom edges).
void parallel_for_tiles(int width, int height, int tile_size, const std::function<void(const tile&)>& f);

// Calls f(begin, end) on chunks of [0, n) in parallel.
void parallel_for_chunks(std::size_t n, std::size_t grain, const std::function<void(std::size_t, std::size_t)>& f);

// Runs a() and b(), in parallel where a thread is free (fork-join: returns when both have).
void parallel_invoke(const std::function<void()>& a, const std::function<void()>& b);

// The threads the loops above may use now: one per core, or fewer under a thread_limit.
int parallel_threads();

// Limits TBB to n threads while alive (n <= 0: no limit, TBB's default of one per core).
class thread_limit {
public:
    explicit thread_limit(int n);
    ~thread_limit();
    thread_limit(const thread_limit&) = delete;
    thread_limit& operator=(const thread_limit&) = delete;

private:
    struct control;
    std::unique_ptr<control> control_;
};

// Keeps the calling thread on one logical CPU while alive, and gives it back the CPUs it had after
// (cpu < 0: changes nothing). For timings of one thread: on a virtual machine whose virtual CPUs run at
// different speeds for a while (another guest on the core behind one of them), a process left free lands on
// one or the other and reads one of two speeds, and the spread across processes measures the placement, not
// the code (chapter 16's NOTES.md, "How much a process moves"). Throws std::invalid_argument naming the CPU
// where this process may not run on it.
class pinned_thread {
public:
    explicit pinned_thread(int cpu);
    ~pinned_thread();
    pinned_thread(const pinned_thread&) = delete;
    pinned_thread& operator=(const pinned_thread&) = delete;

private:
    struct saved;
    std::unique_ptr<saved> saved_;
};

// The lowest-numbered CPU this process may run on (0 where the system does not say).
int first_allowed_cpu();

// Whether this process may run on CPU cpu.
bool cpu_allowed(int cpu);

}  // namespace strahl
