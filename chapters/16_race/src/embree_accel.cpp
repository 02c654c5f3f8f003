#include "strahl/race/embree_accel.hpp"
#include <stdexcept>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace strahl::race {

// MXCSR bit 15 is flush-to-zero (results that would be denormal become 0), bit 6 denormals-are-zero
// (denormal inputs read as 0).
#if defined(__SSE__)
constexpr unsigned ftz_daz_bits = (1u << 15) | (1u << 6);
denormals_flushed::denormals_flushed() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | ftz_daz_bits); }
denormals_flushed::~denormals_flushed() { _mm_setcsr(saved_); }
bool denormals_are_flushed() { return (_mm_getcsr() & ftz_daz_bits) == ftz_daz_bits; }
#else
denormals_flushed::denormals_flushed() {}
denormals_flushed::~denormals_flushed() {}
bool denormals_are_flushed() { return false; }
#endif

std::string embree_report::summary() const {
    if (version.empty()) return "no Embree";
    return "Embree " + version + ", " + (kernels.empty() ? std::string("unknown") : kernels) + " kernels";
}

}  // namespace strahl::race

#ifndef STRAHL_HAVE_EMBREE

namespace strahl::race {
bool embree_available() { return false; }
std::unique_ptr<accel> make_embree_accel(const embree_config&) {
    throw std::runtime_error("this build has no Embree 3 (install libembree-dev: ./course setup)");
}
const embree_report& embree_configuration() {
    static const embree_report none;
    return none;
}
}  // namespace strahl::race

#else

#include "strahl/race/brute_force.hpp"
#include "strahl/ch10/accel.hpp"
#include "strahl/instancing.hpp"
#include <cmath>
#include <embree3/rtcore.h>
#include <algorithm>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
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
    }
}

class embree_accel final : public accel {
public:
    explicit embree_accel(const embree_config& c) : config_(c) {
        const std::string options = "threads=" + std::to_string(c.threads > 0 ? c.threads : 0);
        const denormals_flushed flushed;  // (so that Embree's start-up check finds FTZ and DAZ set)
        device_ = rtcNewDevice(options.c_str());
        if (!device_) throw std::runtime_error("Embree: rtcNewDevice failed (error " + std::to_string(rtcGetDeviceError(nullptr)) + ")");
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
        return config_.packet_image_width > 0 ? n + "-packet8" : n;
    }
    bool exact() const override { return false; }
    std::size_t batch_alignment() const override {
        return config_.packet_image_width > 0 ? 2 * std::size_t(config_.packet_image_width) : 1;
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
        if (config_.instanced) return build_instanced(s);
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
            bytes_ = nv * 12 + nt * 12;
            vertices_ = nv, triangles_ = nt;
        }
        rtcCommitScene(scene_);
        if (const RTCError e = rtcGetDeviceError(device_); e != RTC_ERROR_NONE)
            throw std::runtime_error("Embree: building the scene failed (error " + std::to_string(int(e)) + ")");
    }

    void intersect(std::span<const ray> rays, std::span<hit> hits) const override {
        const denormals_flushed flushed;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        const int w = config_.packet_image_width;
        if (w > 0 && w % 4 == 0 && rays.size() % std::size_t(2 * w) == 0 &&
            std::all_of(rays.begin(), rays.end(), embree_takes)) {
            intersect_tiles(rays, hits, &context);
            return;
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
        rtcInitIntersectContext(&context);
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

    // Embree does not say how much memory its BVH takes; this is the geometry it copied.
    std::size_t memory_bytes() const override { return bytes_; }

private:
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
            bytes_ += m.positions.size() * 12 + m.triangle_count() * 12;
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
        bytes_ += instances_->instances.size() * sizeof(instance);
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

    // rtcIntersect8 on 4x2 pixel tiles: rays x..x+3 of rows y and y+1 of a scanline-ordered image.
    void intersect_tiles(std::span<const ray> rays, std::span<hit> hits, RTCIntersectContext* context) const {
        const std::size_t w = std::size_t(config_.packet_image_width), rows = rays.size() / w;
        alignas(32) int valid[8];
        for (int& x : valid) x = -1;
        for (std::size_t y = 0; y < rows; y += 2)
            for (std::size_t x = 0; x < w; x += 4) {
                alignas(32) RTCRayHit8 p;
                std::size_t index[8];
                for (int lane = 0; lane < 8; ++lane) {
                    index[lane] = (y + lane / 4) * w + x + lane % 4;
                    const RTCRayHit one = to_embree(rays[index[lane]]);
                    p.ray.org_x[lane] = one.ray.org_x; p.ray.org_y[lane] = one.ray.org_y; p.ray.org_z[lane] = one.ray.org_z;
                    p.ray.dir_x[lane] = one.ray.dir_x; p.ray.dir_y[lane] = one.ray.dir_y; p.ray.dir_z[lane] = one.ray.dir_z;
                    p.ray.tnear[lane] = one.ray.tnear; p.ray.tfar[lane] = one.ray.tfar;
                    p.ray.time[lane] = 0.0f; p.ray.mask[lane] = 0xFFFFFFFFu; p.ray.id[lane] = unsigned(lane);
                    p.ray.flags[lane] = 0;
                    p.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
                    p.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
                }
                rtcIntersect8(valid, scene_, context, &p);
                for (int lane = 0; lane < 8; ++lane)
                    hits[index[lane]] = from_embree(p.ray.tfar[lane], p.hit.geomID[lane], p.hit.primID[lane],
                                                    p.hit.u[lane], p.hit.v[lane]);
            }
    }

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
    std::size_t bytes_ = 0;
};

}  // namespace

bool embree_available() { return true; }

const embree_report& embree_configuration() {
    static const embree_report report = [] {
        embree_report r;
        // A device created with verbose=1 prints Embree's configuration on std::cout (the same stream object:
        // libstdc++ is shared), read here through a string buffer.
        std::ostringstream captured;
        std::streambuf* const saved = std::cout.rdbuf(captured.rdbuf());
        RTCDevice device;
        {
            const denormals_flushed flushed;
            device = rtcNewDevice("verbose=1,threads=1");
        }
        std::cout.rdbuf(saved);
        if (!device) return r;
        const long v = long(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION));
        r.version = std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." + std::to_string(v % 100);
        rtcReleaseDevice(device);
        // "    Targets : SSE2 SSE4.2 AVX AVX2 AVX512  (supported)" then "    ... (compile time enabled)".
        std::istringstream lines(captured.str());
        for (std::string line; std::getline(lines, line);) {
            const auto list = [&](const char* tag) {
                const std::size_t end = line.find(tag);
                if (end == std::string::npos) return false;
                std::size_t begin = line.find("Targets :");
                begin = begin == std::string::npos ? 0 : begin + 9;
                std::istringstream words(line.substr(begin, end - begin));
                std::string all, w;
                while (words >> w) all += (all.empty() ? "" : " ") + w;
                (std::string(tag) == "(supported)" ? r.supported : r.compiled) = all;
                return true;
            };
            if (!list("(supported)")) list("(compile time enabled)");
        }
        // Embree runs the widest target both compiled in and supported by the CPU.
        std::istringstream supported(r.supported);
        for (std::string t; supported >> t;)
            if ((" " + r.compiled + " ").find(" " + t + " ") != std::string::npos) r.kernels = t;
        return r;
    }();
    return report;
}

std::unique_ptr<accel> make_embree_accel(const embree_config& config) { return std::make_unique<embree_accel>(config); }

}  // namespace strahl::race

#endif
