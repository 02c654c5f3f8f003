// Embree 3 behind the course's accel interface (embree_accel.hpp); what Embree runs: embree_report.cpp.
#include "strahl/race/embree_accel.hpp"
#include <stdexcept>

#ifndef STRAHL_HAVE_EMBREE

namespace strahl::race {
bool embree_available() { return false; }
std::unique_ptr<accel> make_embree_accel(const embree_config&) {
    throw std::runtime_error("this build has no Embree 3 (install libembree-dev: ./course setup)");
}
}  // namespace strahl::race

#else

#include "strahl/race/brute_force.hpp"
#include "strahl/ch10/accel.hpp"
#include "strahl/instancing.hpp"
#include <algorithm>
#include <atomic>
#include <cmath>
#include <embree3/rtcore.h>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace strahl::race {

namespace {

// Whether Embree accepts the ray: its traversal asserts tnear >= 0 and origin and direction components within
// FLT_LARGE (1.844e18), and aborts the process otherwise (Debian's build keeps the assertions). The wrapper
// answers the other rays with brute force (the course's own answer), never passing them to Embree.
bool embree_takes(const ray& r) {
    constexpr float large = 1.844e18f;
    const auto ok = [&](const vec3& v) { return std::fabs(v.x) <= large && std::fabs(v.y) <= large && std::fabs(v.z) <= large; };
    return r.tmin >= 0.0f && !std::isnan(r.tmax) && ok(r.org) && ok(r.dir);
}

// The probe's filter function (embree_call_probe): runs inside Embree's traversal at every candidate hit.
void probe_filter(const RTCFilterFunctionNArguments* args) {
    auto* probe = static_cast<embree_call_probe*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const float tnear = RTCRayN_tnear(args->ray, args->N, i);
        probe->candidate_hits.fetch_add(1, std::memory_order_relaxed);
        if (!denormals_are_flushed()) probe->without_ftz_daz.fetch_add(1, std::memory_order_relaxed);
        if (std::fpclassify(tnear) == FP_SUBNORMAL) probe->denormal_tnear.fetch_add(1, std::memory_order_relaxed);
        if (args->context && args->context->flags == RTC_INTERSECT_CONTEXT_FLAG_COHERENT)
            probe->coherent.fetch_add(1, std::memory_order_relaxed);
    }
}

class embree_accel final : public accel {
public:
    explicit embree_accel(const embree_config& c) : config_(c) {
        if (c.instanced && c.queries != embree_config::calls::single)
            throw std::invalid_argument("Embree's instanced rows trace one ray at a time (no packets or streams)");
        const std::string options = "threads=" + std::to_string(c.threads > 0 ? c.threads : 0);
        const denormals_flushed flushed;  // (so that Embree's start-up check finds FTZ and DAZ set)
        device_ = rtcNewDevice(options.c_str());
        if (!device_) throw std::runtime_error("Embree: rtcNewDevice failed (error " + std::to_string(rtcGetDeviceError(nullptr)) + ")");
        rtcSetDeviceMemoryMonitorFunction(device_, &embree_accel::monitor, this);
    }
    ~embree_accel() override {
        release();
        rtcReleaseDevice(device_);
    }

    std::string name() const override {
        using q = embree_config::quality;
        std::string n = config_.build_quality == q::high  ? "embree-high"
                        : config_.build_quality == q::low ? "embree-low"
                                                          : "embree-medium";
        if (config_.instanced) n += "-instanced";
        using c = embree_config::calls;
        n += config_.queries == c::packet8    ? "-packet8"
             : config_.queries == c::packet16 ? "-packet16"
             : config_.queries == c::stream   ? "-stream"
                                              : "";
        return config_.coherent ? n + "-coherent" : n;
    }
    bool exact() const override { return false; }
    // The packet and stream calls: whole rows of tiles (consecutive rays where there are no rows), so that
    // the race's thread chunks cut no tile.
    std::size_t batch_alignment() const override {
        if (config_.queries == embree_config::calls::single) return 1;
        const tile_shape t = tile();
        return config_.packet_image_width > 0 ? t.height * std::size_t(config_.packet_image_width) : t.width;
    }

    void build(const scene& s) override {
        {
            const std::lock_guard<std::mutex> lock(fallback_mutex_);
            fallback_.reset();
        }
        release();
        instances_.reset();
        bytes_ = 0;
        vertices_ = triangles_ = 0;
        const long long before = held_.load();
        if (config_.instanced) build_instanced(s);
        else build_plain(s);
        bytes_ = std::size_t(std::max(0LL, held_.load() - before));
    }

    // Everything Embree holds for the scene after its build, as its device's memory monitor counts it: the
    // BVH, its leaves (Embree copies the triangles' vertices into them) and the geometry buffers it owns.
    std::size_t memory_bytes() const override { return bytes_; }

    void intersect(std::span<const ray> rays, std::span<hit> hits) const override {
        const denormals_flushed flushed;
        RTCIntersectContext context;
        init(context);
        using c = embree_config::calls;
        switch (config_.queries) {
        case c::packet8: return trace_tiles<embree_packet<8, true>>(rays, hits, &context);
        case c::packet16: return trace_tiles<embree_packet<16, true>>(rays, hits, &context);
        case c::stream: return trace_tiles<embree_stream<64, true>>(rays, hits, &context);
        case c::single: break;
        }
        for (std::size_t i = 0; i < rays.size(); ++i) {
            if (!embree_takes(rays[i])) {
                fallback().intersect(rays.subspan(i, 1), hits.subspan(i, 1));
                continue;
            }
            RTCRayHit rh = to_embree(rays[i]);
            rtcIntersect1(scene_, &context, &rh);
            hits[i] = from_embree(rh.ray.tfar, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v);
            if (config_.instanced && hits[i].found())
                hits[i].inst = rh.hit.instID[0], hits[i].prim += first_ids_[rh.hit.instID[0]];
        }
    }

    void occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const override {
        const denormals_flushed flushed;
        RTCIntersectContext context;
        init(context);
        using c = embree_config::calls;
        switch (config_.queries) {
        case c::packet8: return trace_tiles<embree_packet<8, false>>(rays, blocked, &context);
        case c::packet16: return trace_tiles<embree_packet<16, false>>(rays, blocked, &context);
        case c::stream: return trace_tiles<embree_stream<64, false>>(rays, blocked, &context);
        case c::single: break;
        }
        for (std::size_t i = 0; i < rays.size(); ++i) {
            if (!embree_takes(rays[i])) {
                fallback().occluded(rays.subspan(i, 1), blocked.subspan(i, 1));
                continue;
            }
            RTCRay r;
            to_embree(rays[i], r);
            rtcOccluded1(scene_, &context, &r);
            blocked[i] = r.tfar == -inf ? 1 : 0;
        }
    }

private:
    // Embree's memory monitor: every allocation (bytes > 0) and release (bytes < 0) of this accel's device.
    static bool monitor(void* self, ssize_t bytes, bool) {
        static_cast<embree_accel*>(self)->held_.fetch_add(static_cast<long long>(bytes));
        return true;
    }

    void build_plain(const scene& s) {
        scene_ = rtcNewScene(device_);
        rtcSetSceneBuildQuality(scene_, quality());
        const std::size_t nv = s.mesh.positions.size(), nt = s.mesh.triangle_count();
        if (nt > 0) {
            RTCGeometry geom = triangles(s.mesh);
            if (config_.probe) {
                rtcSetGeometryUserData(geom, config_.probe);
                rtcSetGeometryIntersectFilterFunction(geom, probe_filter);
                rtcSetGeometryOccludedFilterFunction(geom, probe_filter);
            }
            rtcCommitGeometry(geom);
            rtcAttachGeometry(scene_, geom);
            rtcReleaseGeometry(geom);
            vertices_ = nv, triangles_ = nt;
        }
        rtcCommitScene(scene_);
        if (const RTCError e = rtcGetDeviceError(device_); e != RTC_ERROR_NONE)
            throw std::runtime_error("Embree: building the scene failed (error " + std::to_string(int(e)) + ")");
    }

    void release() {
        if (scene_) rtcReleaseScene(scene_);
        for (RTCScene m : mesh_scenes_) rtcReleaseScene(m);
        scene_ = nullptr;
        mesh_scenes_.clear();
    }
    // A triangle geometry over the mesh: Embree copies into buffers it owns (and pads for its 16-byte loads).
    RTCGeometry triangles(const triangle_mesh& mesh) {
        const std::size_t nv = mesh.positions.size(), nt = mesh.triangle_count();
        RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuildQuality(geom, quality());
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), nv));
        for (std::size_t i = 0; i < nv; ++i)
            for (int k = 0; k < 3; ++k) v[3 * i + k] = mesh.positions[i][k];
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                  3 * sizeof(unsigned), nt));
        for (std::size_t i = 0; i < nt; ++i)
            for (int k = 0; k < 3; ++k) idx[3 * i + k] = mesh.indices[i][k];
        return geom;
    }
    // Embree's instancing: a scene per mesh, an instance geometry per instance (geometry id = instance id).
    void build_instanced(const scene& s) {
        instances_ = std::make_shared<const instanced_meshes>(ch10::instances_of(s));
        first_ids_ = instances_->first_ids();
        for (const triangle_mesh& m : instances_->meshes) {
            RTCScene ms = rtcNewScene(device_);
            rtcSetSceneBuildQuality(ms, quality());
            if (m.triangle_count() > 0) {
                RTCGeometry g = triangles(m);
                rtcCommitGeometry(g);
                rtcAttachGeometry(ms, g);
                rtcReleaseGeometry(g);
            }
            rtcCommitScene(ms);
            mesh_scenes_.push_back(ms);
        }
        scene_ = rtcNewScene(device_);
        rtcSetSceneBuildQuality(scene_, quality());
        for (std::size_t i = 0; i < instances_->instances.size(); ++i) {
            const instance& in = instances_->instances[i];
            RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(g, mesh_scenes_[in.mesh]);
            rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, &in.to_world.m[0][0]);
            rtcCommitGeometry(g);
            rtcAttachGeometryByID(scene_, g, unsigned(i));
            rtcReleaseGeometry(g);
        }
        rtcCommitScene(scene_);
        if (const RTCError e = rtcGetDeviceError(device_); e != RTC_ERROR_NONE)
            throw std::runtime_error("Embree: building the instanced scene failed (error " + std::to_string(int(e)) + ")");
    }
    RTCBuildQuality quality() const {
        using q = embree_config::quality;
        return config_.build_quality == q::high  ? RTC_BUILD_QUALITY_HIGH
               : config_.build_quality == q::low ? RTC_BUILD_QUALITY_LOW
                                                 : RTC_BUILD_QUALITY_MEDIUM;
    }
    // The course's rays are open intervals (tmin, tmax). Embree's triangle test already excludes t = tnear
    // (absDen * tnear < T) but accepts t = tfar (T <= absDen * tfar): tnear is tmin, and tfar is tmax moved
    // inwards by one ulp. (tnear = nextafter(tmin) would be a denormal for tmin = 0: slow, and read as 0
    // anyway with denormals-are-zero on.)
    // Every field written once, nothing zeroed twice: this runs once per ray.
    static void to_embree(const ray& r, RTCRay& e) {
        e.org_x = r.org.x; e.org_y = r.org.y; e.org_z = r.org.z;
        e.tnear = r.tmin;
        e.dir_x = r.dir.x; e.dir_y = r.dir.y; e.dir_z = r.dir.z;
        e.time = 0.0f;
        e.tfar = r.tmax == inf ? inf : std::nextafter(r.tmax, -inf);
        e.mask = 0xFFFFFFFFu;
        e.id = 0;
        e.flags = 0;
    }
    static RTCRayHit to_embree(const ray& r) {
        RTCRayHit rh;
        to_embree(r, rh.ray);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        return rh;
    }
    static hit from_embree(float tfar, unsigned geom, unsigned prim, float u, float v) {
        if (geom == RTC_INVALID_GEOMETRY_ID) return hit{};
        return hit{tfar, prim, u, v, invalid_id};
    }

    // One packet call's rays in Embree's structure-of-arrays layout (RTCRayHit8/16 for closest hits,
    // RTCRay8/16 for any hits), and its valid mask: -1 for a lane set, 0 for the others. The layout is
    // zeroed once, so that an invalid lane holds zeros or an earlier tile's ray, never garbage.
    template <int N, bool Closest>
    struct embree_packet {
        static constexpr std::size_t lanes = N;
        using rays_n = std::conditional_t<N == 8, RTCRay8, RTCRay16>;
        using layout = std::conditional_t<Closest, std::conditional_t<N == 8, RTCRayHit8, RTCRayHit16>, rays_n>;
        alignas(64) int lane_mask[N];
        layout p{};

        rays_n& rays() {
            if constexpr (Closest) return p.ray;
            else return p;
        }
        void clear() {
            for (int& m : lane_mask) m = 0;
        }
        void set(std::size_t lane, const ray& r) {
            RTCRay one;
            to_embree(r, one);
            rays_n& q = rays();
            q.org_x[lane] = one.org_x; q.org_y[lane] = one.org_y; q.org_z[lane] = one.org_z;
            q.dir_x[lane] = one.dir_x; q.dir_y[lane] = one.dir_y; q.dir_z[lane] = one.dir_z;
            q.tnear[lane] = one.tnear; q.tfar[lane] = one.tfar;
            q.time[lane] = 0.0f; q.mask[lane] = 0xFFFFFFFFu; q.id[lane] = unsigned(lane); q.flags[lane] = 0;
            if constexpr (Closest) {
                p.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
                p.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
            }
            lane_mask[lane] = -1;
        }
        bool valid(std::size_t lane) const { return lane_mask[lane] == -1; }
        void trace(RTCScene scene, RTCIntersectContext* context) {
            if constexpr (Closest && N == 8) rtcIntersect8(lane_mask, scene, context, &p);
            else if constexpr (Closest) rtcIntersect16(lane_mask, scene, context, &p);
            else if constexpr (N == 8) rtcOccluded8(lane_mask, scene, context, &p);
            else rtcOccluded16(lane_mask, scene, context, &p);
        }
        void get(std::size_t lane, hit& h) const {
            h = from_embree(p.ray.tfar[lane], p.hit.geomID[lane], p.hit.primID[lane], p.hit.u[lane], p.hit.v[lane]);
        }
        void get(std::size_t lane, std::uint8_t& blocked) const { blocked = p.tfar[lane] == -inf ? 1 : 0; }
    };

    // One stream call's rays, Embree's single-ray structures one after another (RTCRayHit for closest hits,
    // RTCRay for any hits): the lanes set, in lane order, and nothing for the others (a stream has no mask);
    // slot[lane] is a lane's place in the stream, -1 for a lane not set.
    template <int M, bool Closest>
    struct embree_stream {
        static constexpr std::size_t lanes = M;
        using element = std::conditional_t<Closest, RTCRayHit, RTCRay>;
        element stream[M];
        int slot[M];
        unsigned count = 0;

        void clear() {
            count = 0;
            for (int& k : slot) k = -1;
        }
        void set(std::size_t lane, const ray& r) {
            if constexpr (Closest) stream[count] = to_embree(r);
            else to_embree(r, stream[count]);
            slot[lane] = int(count++);
        }
        bool valid(std::size_t lane) const { return slot[lane] >= 0; }
        void trace(RTCScene scene, RTCIntersectContext* context) {
            if (count == 0) return;
            if constexpr (Closest) rtcIntersect1M(scene, context, stream, count, sizeof(element));
            else rtcOccluded1M(scene, context, stream, count, sizeof(element));
        }
        void get(std::size_t lane, hit& h) const {
            const RTCRayHit& e = stream[slot[lane]];
            h = from_embree(e.ray.tfar, e.hit.geomID, e.hit.primID, e.hit.u, e.hit.v);
        }
        void get(std::size_t lane, std::uint8_t& blocked) const { blocked = stream[slot[lane]].tfar == -inf ? 1 : 0; }
    };

    // The context of every call: Embree's default, and the coherent flag where the configuration asks for it.
    void init(RTCIntersectContext& context) const {
        rtcInitIntersectContext(&context);
        if (config_.coherent) context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    }

    // A tile of the packet and stream calls, in rays: 4x2 (packet8), 4x4 (packet16), 8x8 (stream). Without
    // rows (packet_image_width 0) a tile is one row of as many consecutive rays.
    struct tile_shape {
        std::size_t width, height;
    };
    tile_shape tile() const {
        using c = embree_config::calls;
        const tile_shape t = config_.queries == c::packet16 ? tile_shape{4, 4}
                             : config_.queries == c::stream ? tile_shape{8, 8}
                                                            : tile_shape{4, 2};
        return config_.packet_image_width > 0 ? t : tile_shape{t.width * t.height, 1};
    }

    // The packet and stream calls, one per tile: the batch's rays are rows of packet_image_width rays, cut
    // into tiles of consecutive rows, left to right, then top to bottom. Batch is one call's rays in
    // Embree's layout (embree_packet, embree_stream); Result is hit (closest) or std::uint8_t (any).
    // A tile that runs past the end of a row or of the batch (a batch that is not whole rows of tiles: the
    // secondary rays, one per primary hit, or a thread's last chunk) is a partial one: its missing lanes
    // are invalid. So is a lane whose ray Embree cannot take (embree_takes): brute force answers it.
    template <class Batch, class Result>
    void trace_tiles(std::span<const ray> rays, std::span<Result> results, RTCIntersectContext* context) const {
        const tile_shape t = tile();
        static_assert(Batch::lanes == 8 || Batch::lanes == 16 || Batch::lanes == 64);
        const std::size_t n = rays.size();
        const std::size_t w = config_.packet_image_width > 0 ? std::size_t(config_.packet_image_width) : t.width;
        Batch batch;
        std::size_t index[Batch::lanes];
        for (std::size_t y = 0; y * w < n; y += t.height)
            for (std::size_t x = 0; x < w && y * w + x < n; x += t.width) {
                // 1. The tile's lanes: lane k is ray (x + k % tile width, y + k / tile width) of the rows.
                batch.clear();
                for (std::size_t lane = 0; lane < Batch::lanes; ++lane) {
                    const std::size_t column = x + lane % t.width, i = (y + lane / t.width) * w + column;
                    index[lane] = i;
                    if (column >= w || i >= n) continue;
                    if (embree_takes(rays[i])) batch.set(lane, rays[i]);
                    else answer_by_fallback(rays.subspan(i, 1), results.subspan(i, 1));
                }
                // 2. One call for the tile, 3. its valid lanes' answers back in the course's form.
                batch.trace(scene_, context);
                for (std::size_t lane = 0; lane < Batch::lanes; ++lane)
                    if (batch.valid(lane)) batch.get(lane, results[index[lane]]);
            }
        // A library built without 16-wide kernels or without packets refuses the calls; a refused call
        // answers nothing, so it must not pass for misses.
        if (const RTCError e = rtcGetDeviceError(device_); e != RTC_ERROR_NONE)
            throw std::runtime_error("Embree: a packet or stream call failed (error " + std::to_string(int(e)) + ")");
    }
    void answer_by_fallback(std::span<const ray> r, std::span<hit> h) const { fallback().intersect(r, h); }
    void answer_by_fallback(std::span<const ray> r, std::span<std::uint8_t> b) const { fallback().occluded(r, b); }

    // Brute force over Embree's own copy of the triangles, for the rays Embree cannot take (embree_takes);
    // made on first need, so that Embree's build and memory stay Embree's.
    const accel& fallback() const {
        const std::lock_guard<std::mutex> lock(fallback_mutex_);
        if (!fallback_ && instances_) {
            // Instanced: chapter 10's instanced brute force over the same instances.
            scene copy;
            copy.instances = instances_;
            fallback_ = ch10::make_brute_accel();
            fallback_->build(copy);
        }
        if (!fallback_) {
            scene copy;
            if (RTCGeometry g = scene_ ? rtcGetGeometry(scene_, 0) : nullptr) {
                const auto* v = static_cast<const float*>(rtcGetGeometryBufferData(g, RTC_BUFFER_TYPE_VERTEX, 0));
                const auto* idx = static_cast<const unsigned*>(rtcGetGeometryBufferData(g, RTC_BUFFER_TYPE_INDEX, 0));
                copy.mesh.positions.resize(vertices_);
                for (std::size_t i = 0; i < vertices_; ++i) copy.mesh.positions[i] = vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
                copy.mesh.indices.resize(triangles_);
                for (std::size_t i = 0; i < triangles_; ++i) copy.mesh.indices[i] = uvec3(idx[3 * i], idx[3 * i + 1], idx[3 * i + 2]);
            }
            fallback_ = std::make_unique<brute_force>();
            fallback_->build(copy);
        }
        return *fallback_;
    }

    embree_config config_;
    mutable std::mutex fallback_mutex_;
    mutable std::unique_ptr<accel> fallback_;
    std::shared_ptr<const instanced_meshes> instances_;  // instanced only
    std::vector<std::uint32_t> first_ids_;               // instanced only: flattened id of each instance's first
    std::vector<RTCScene> mesh_scenes_;                  // instanced only: one per mesh
    std::size_t vertices_ = 0, triangles_ = 0;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::size_t bytes_ = 0;               // memory_bytes(): held_ after the build less before it
    std::atomic<long long> held_{0};      // bytes the device holds now (monitor)
};

}  // namespace

bool embree_available() { return true; }

std::unique_ptr<accel> make_embree_accel(const embree_config& config) { return std::make_unique<embree_accel>(config); }

}  // namespace strahl::race

#endif
