// bench_embree: checks the race's yardstick. Times, in one process and in alternating rounds on the same
// rays, Embree as the race calls it (embree_accel.cpp) against a minimal harness that calls rtcIntersect1 /
// rtcOccluded1 directly, as Embree's documentation asks (tnear = 0, flush-to-zero and denormals-are-zero set),
// and against the call the race made before (tnear = nextafter(0), a denormal, with IEEE denormals), to show
// what that cost. Prints each call's median Mrays/s and the median of its per-round ratios to the harness.
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/race/brute_force.hpp"
#include "strahl/race/embree_accel.hpp"
#include "strahl/race/ray_sets.hpp"
#include "strahl/timer.hpp"
#include <cmath>
#include <cstdio>
#include <embree3/rtcore.h>
#include <iostream>

using namespace strahl;
using namespace strahl::race;

namespace {

// The minimal harness: Embree's scene built the plain way, one rtcIntersect1 or rtcOccluded1 per ray.
class harness {
public:
    explicit harness(const scene& s) {
        device_ = rtcNewDevice("threads=1");
        scene_ = rtcNewScene(device_);
        rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              12, s.mesh.positions.size()));
        for (std::size_t i = 0; i < s.mesh.positions.size(); ++i)
            for (int k = 0; k < 3; ++k) v[3 * i + k] = s.mesh.positions[i][k];
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   12, s.mesh.indices.size()));
        for (std::size_t i = 0; i < s.mesh.indices.size(); ++i)
            for (int k = 0; k < 3; ++k) idx[3 * i + k] = s.mesh.indices[i][k];
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene_, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(scene_);
    }
    ~harness() {
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    // tnear as given; the caller sets MXCSR.
    // Answers stored as the race stores them (a hit record or a flag per ray), so both do the same work.
    std::size_t closest(std::span<const ray> rays, std::span<hit> hits, float tnear) const {
        RTCIntersectContext c;
        rtcInitIntersectContext(&c);
        std::size_t found = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            RTCRayHit rh{};
            set(rh.ray, rays[i], tnear);
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene_, &c, &rh);
            const bool h = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            hits[i] = h ? hit{rh.ray.tfar, rh.hit.primID, rh.hit.u, rh.hit.v, invalid_id} : hit{};
            found += h;
        }
        return found;
    }
    std::size_t any(std::span<const ray> rays, std::span<std::uint8_t> blocked, float tnear) const {
        RTCIntersectContext c;
        rtcInitIntersectContext(&c);
        std::size_t found = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            RTCRay e{};
            set(e, rays[i], tnear);
            rtcOccluded1(scene_, &c, &e);
            blocked[i] = e.tfar == -inf;
            found += blocked[i];
        }
        return found;
    }

private:
    static void set(RTCRay& e, const ray& r, float tnear) {
        e.org_x = r.org.x, e.org_y = r.org.y, e.org_z = r.org.z;
        e.dir_x = r.dir.x, e.dir_y = r.dir.y, e.dir_z = r.dir.z;
        e.tnear = tnear;
        e.tfar = r.tmax == inf ? inf : std::nextafter(r.tmax, -inf);
        e.mask = ~0u;
    }
    RTCDevice device_;
    RTCScene scene_;
};

int run(int argc, const char* const* argv) {
    cli args("bench_embree",
             "Embree as the race calls it, against a minimal rtcIntersect1 harness called as Embree's documentation\n"
             "asks and against the former call (denormal tnear, IEEE denormals): same rays, alternating rounds.");
    args.option("scene", "FILE|builtin:NAME", "builtin:teapot", "the scene")
        .option("gen", "KIND", "primary", "the rays: primary, diffuse (closest hit) or shadow (any hit)")
        .option("width", "W", "192", "image width of the rays")
        .option("height", "H", "144", "image height")
        .option("rounds", "N", "15", "rounds; each times every call once, in rotating order")
        .flag("harness-first", "build the harness's scene before the race's (the order moves speeds by up to a "
                               "fifth here: run both)");
    if (!args.parse(argc, argv)) return 0;
    const int rounds = args.get_int("rounds"), w = args.get_int("width"), h = args.get_int("height");
    if (rounds < 1 || rounds > 10000 || w < 1 || h < 1 || w > 4096 || h > 4096)
        throw usage_error("need --rounds in 1..10000 and --width, --height in 1..4096");
    const scene s = load_scene_spec(args.get("scene"), &std::cout);
    const ray_kind kind = parse_ray_kind(args.get("gen"));
    brute_force exact;
    exact.build(s);
    const std::vector<ray> rays = make_rays(kind, s, w, h, 1, exact, 1);
    const bool any = is_any_hit(kind);
    for (const ray& r : rays)
        if (r.tmin != 0.0f) throw std::runtime_error("bench_embree expects rays with tmin = 0");

    // Which scene is allocated first changes both speeds (memory placement): --harness-first swaps the order.
    std::unique_ptr<harness> early;
    if (args.has("harness-first")) early = std::make_unique<harness>(s);
    const std::unique_ptr<accel> wrapper = make_embree_accel({});
    wrapper->build(s);
    const std::unique_ptr<harness> late = early ? nullptr : std::make_unique<harness>(s);
    const harness& minimal = early ? *early : *late;
    std::vector<hit> hits(rays.size());
    std::vector<std::uint8_t> blocked(rays.size());
    const float denormal = std::nextafter(0.0f, 1.0f);
    const char* const names[3] = {"the race's call (embree_accel.cpp)", "minimal: tnear 0, FTZ+DAZ on",
                                  "former: tnear 1.4e-45, FTZ+DAZ off"};
    std::size_t found[3] = {0, 0, 0};
    const auto call = [&](int which) {
        if (which == 0) {
            if (any) wrapper->occluded(rays, blocked);
            else wrapper->intersect(rays, hits);
            std::size_t n = 0;
            for (std::size_t i = 0; i < rays.size(); ++i) n += any ? blocked[i] : hits[i].found();
            return n;
        }
        if (which == 1) {
            const denormals_flushed flushed;
            return any ? minimal.any(rays, blocked, 0.0f) : minimal.closest(rays, hits, 0.0f);
        }
        return any ? minimal.any(rays, blocked, denormal) : minimal.closest(rays, hits, denormal);
    };
    for (int k = 0; k < 3; ++k) found[k] = call(k);  // warm-up
    std::vector<double> ms[3], ratio[3];
    for (int round = 0; round < rounds; ++round) {
        double t[3];
        for (int j = 0; j < 3; ++j) {
            const int k = (round + j) % 3;
            timer clock;
            call(k);
            t[k] = clock.milliseconds();
        }
        for (int k = 0; k < 3; ++k) ms[k].push_back(t[k]), ratio[k].push_back(t[1] / t[k]);
    }
    std::printf("%s, %zu %s rays (%s), %d rounds, one thread, %s scene built first; %s\n", s.name.c_str(),
                rays.size(), args.get("gen").c_str(), any ? "any hit" : "closest hit", rounds,
                early ? "the harness's" : "the race's", embree_configuration().summary().c_str());
    std::printf("%-40s %10s %12s %8s\n", "call", "Mrays/s", "x minimal", "hits");
    for (int k = 0; k < 3; ++k)
        std::printf("%-40s %10.3f %12.3f %8zu\n", names[k], double(rays.size()) / median(ms[k]) * 1e-3,
                    median(ratio[k]), found[k]);
    std::printf("(x minimal: the median over rounds of the harness's time over this call's; 1 is as fast)\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) { return guarded_main("bench_embree", run, argc, argv); }
