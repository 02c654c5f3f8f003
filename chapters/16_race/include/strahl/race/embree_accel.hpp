// Embree 3 (Wald et al., "Embree: A Kernel Framework for Efficient CPU Ray Tracing", SIGGRAPH 2014) behind
// the course's accel interface: the baseline every chapter is measured against, and an independent oracle.
// Embree has its own triangle test, so its answers may differ from brute force on a handful of edge cases:
// exact() is false and the race counts the differences instead of demanding none.
//
// Embree is called the way its documentation asks, so that the race's yardstick is Embree's real speed:
// - "flush to zero" and "denormals are zero" are set in MXCSR around every batch of Embree's queries, and
//   restored afterwards (the course's own arithmetic, which must equal brute force bit for bit, keeps the
//   IEEE defaults);
// - the ray's tnear is the course's tmin itself, never a denormal. The course's interval (tmin, tmax) is open;
//   Embree's triangle test accepts a hit when absDen * tnear < T (Moeller-Trumbore in un-divided form), a
//   strict comparison, so t = tmin is already excluded; the far end is closed in Embree (T <= absDen * tfar),
//   so tfar is tmax moved inwards by one ulp.
#pragma once
#include "strahl/embree_report.hpp"
#include "strahl/accel.hpp"
#include "strahl/denormals.hpp"
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

namespace strahl::race {

// What the wrapper saw of Embree's arithmetic state in the middle of its queries: Embree calls a filter
// function for every candidate hit, and the probe's filter records MXCSR, the ray's tnear and the call's
// context flags there. Tests attach one to check the yardstick; the race never does (a filter function
// slows Embree down).
struct embree_call_probe {
    std::atomic<std::uint64_t> candidate_hits{0};   // filter calls
    std::atomic<std::uint64_t> without_ftz_daz{0};  // ... with flush-to-zero or denormals-are-zero off
    std::atomic<std::uint64_t> denormal_tnear{0};   // ... for a ray whose tnear is a denormal
    std::atomic<std::uint64_t> coherent{0};         // ... in a call whose context has the coherent flag
};

struct embree_config {
    enum class quality { low, medium, high } build_quality = quality::medium;  // low: Embree's Morton-code build
    // The packet and stream calls see a batch as rows of this many rays (the race's image width: its rays
    // are in scanline order, and secondary rays in the order of their primary hits) and trace tiles of
    // consecutive rows; 0: one row, the tiles are consecutive rays.
    int packet_image_width = 0;
    int threads = 1;  // Embree's own build threads
    // How the rays reach Embree, both queries alike:
    // - single: one at a time, rtcIntersect1 / rtcOccluded1;
    // - packet8: rtcIntersect8 / rtcOccluded8 on tiles of 4x2 rays;
    // - packet16: rtcIntersect16 / rtcOccluded16 on tiles of 4x4 rays;
    // - stream: rtcIntersect1M / rtcOccluded1M, a stream of the 64 rays of an 8x8 tile.
    // Where a tile runs past the end of a row or of the batch, its missing lanes are invalid (a stream
    // leaves them out), as are the rays Embree cannot take, which brute force answers one by one.
    enum class calls { single, packet8, packet16, stream } queries = calls::single;
    // RTC_INTERSECT_CONTEXT_FLAG_COHERENT: tells Embree the rays of a call are coherent, so that it may take
    // its coherent code paths (a packet traversed as a frustum; streams sorted into packets); otherwise
    // the default, INCOHERENT.
    bool coherent = false;
    // Embree's own instancing (chapter 10's yardstick): one Embree scene per mesh of scene.instances, one
    // instance geometry per instance with its transform; hits report the flattened id and the instance. A
    // scene without instances is one instance of its mesh. One ray at a time (single calls only).
    bool instanced = false;
    embree_call_probe* probe = nullptr;  // tests only: record MXCSR, tnear and flags at every candidate hit
};

// Whether this build found Embree 3 (find_package(embree 3)).
bool embree_available();

// Throws std::runtime_error where Embree is not available, std::invalid_argument for instanced packets.
std::unique_ptr<accel> make_embree_accel(const embree_config& config);

// Embree's own account of itself (version, kernels): strahl/embree_report.hpp.
using strahl::embree_configuration;
using strahl::embree_report;

// Flush-to-zero and denormals-are-zero around Embree's calls (strahl/denormals.hpp).
using strahl::denormals_are_flushed;
using strahl::denormals_flushed;

}  // namespace strahl::race
