// Traversal counters, switched in or out at compile time.
//
// Code that traverses takes a counters type as a template parameter and calls e.g. stats.box_test().
// counters<true> counts; counters<false> has the same interface, holds nothing, and every call compiles to
// nothing, so the fast build pays zero. (common/bench_stats.cpp measures that claim: ./course chapter ...
// is not needed, run build/release/bin/bench_stats.) One binary can hold both instantiations: the race
// measures speed with counters<false> and tests per ray with counters<true>.
#pragma once
#include <cstdint>

namespace strahl {

struct counter_values {
    std::uint64_t rays = 0;           // rays traced
    std::uint64_t box_tests = 0;      // ray/box slab tests
    std::uint64_t prim_tests = 0;     // ray/primitive intersection tests
    std::uint64_t nodes_visited = 0;  // nodes (or cells) entered

    counter_values& operator+=(const counter_values& o) {
        rays += o.rays; box_tests += o.box_tests; prim_tests += o.prim_tests; nodes_visited += o.nodes_visited;
        return *this;
    }
    double per_ray(std::uint64_t n) const { return rays ? double(n) / double(rays) : 0.0; }
};

template <bool enabled>
struct counters;

template <>
struct counters<true> {
    static constexpr bool enabled = true;
    counter_values v;
    void ray(std::uint64_t n = 1) { v.rays += n; }
    void box_test(std::uint64_t n = 1) { v.box_tests += n; }
    void prim_test(std::uint64_t n = 1) { v.prim_tests += n; }
    void node_visit(std::uint64_t n = 1) { v.nodes_visited += n; }
    counter_values values() const { return v; }
    void merge(const counters& o) { v += o.v; }
};

template <>
struct counters<false> {
    static constexpr bool enabled = false;
    void ray(std::uint64_t = 1) {}
    void box_test(std::uint64_t = 1) {}
    void prim_test(std::uint64_t = 1) {}
    void node_visit(std::uint64_t = 1) {}
    counter_values values() const { return {}; }
    void merge(const counters&) {}
};

using counting = counters<true>;
using not_counting = counters<false>;

}  // namespace strahl
