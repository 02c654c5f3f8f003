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

#include <embree3/rtcore.h>
#include <string>
#include <vector>

namespace strahl::race {

namespace {

class embree_accel final : public accel {
public:
    explicit embree_accel(const embree_config& c) : config_(c) {
        const std::string options = "threads=" + std::to_string(c.threads > 0 ? c.threads : 0);
        device_ = rtcNewDevice(options.c_str());
        if (!device_) throw std::runtime_error("Embree: rtcNewDevice failed (error " + std::to_string(rtcGetDeviceError(nullptr)) + ")");
    }
    ~embree_accel() override {
        if (scene_) rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }

    std::string name() const override {
        std::string n = config_.build_quality == embree_config::quality::high ? "embree-high" : "embree-medium";
        return config_.packet_image_width > 0 ? n + "-packet8" : n;
    }
    bool exact() const override { return false; }
    std::size_t batch_alignment() const override {
        return config_.packet_image_width > 0 ? 2 * std::size_t(config_.packet_image_width) : 1;
    }

    void build(const scene& s) override {
        if (scene_) rtcReleaseScene(scene_);
        scene_ = rtcNewScene(device_);
        rtcSetSceneBuildQuality(scene_, config_.build_quality == embree_config::quality::high ? RTC_BUILD_QUALITY_HIGH
                                                                                              : RTC_BUILD_QUALITY_MEDIUM);
        const std::size_t nv = s.mesh.positions.size(), nt = s.mesh.triangle_count();
        bytes_ = 0;
        if (nt > 0) {
            RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
            rtcSetGeometryBuildQuality(geom, config_.build_quality == embree_config::quality::high ? RTC_BUILD_QUALITY_HIGH
                                                                                                   : RTC_BUILD_QUALITY_MEDIUM);
            // Embree copies into buffers it owns (and pads for its 16-byte loads).
            auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                   3 * sizeof(float), nv));
            for (std::size_t i = 0; i < nv; ++i)
                for (int k = 0; k < 3; ++k) v[3 * i + k] = s.mesh.positions[i][k];
            auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                      3 * sizeof(unsigned), nt));
            for (std::size_t i = 0; i < nt; ++i)
                for (int k = 0; k < 3; ++k) idx[3 * i + k] = s.mesh.indices[i][k];
            rtcCommitGeometry(geom);
            rtcAttachGeometry(scene_, geom);
            rtcReleaseGeometry(geom);
            bytes_ = nv * 12 + nt * 12;
        }
        rtcCommitScene(scene_);
        if (const RTCError e = rtcGetDeviceError(device_); e != RTC_ERROR_NONE)
            throw std::runtime_error("Embree: building the scene failed (error " + std::to_string(int(e)) + ")");
    }

    void intersect(std::span<const ray> rays, std::span<hit> hits) const override {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        const int w = config_.packet_image_width;
        if (w > 0 && w % 4 == 0 && rays.size() % std::size_t(2 * w) == 0) {
            intersect_tiles(rays, hits, &context);
            return;
        }
        for (std::size_t i = 0; i < rays.size(); ++i) {
            RTCRayHit rh = to_embree(rays[i]);
            rtcIntersect1(scene_, &context, &rh);
            hits[i] = from_embree(rh.ray.tfar, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v);
        }
    }

    void occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const override {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            RTCRay r = to_embree(rays[i]).ray;
            rtcOccluded1(scene_, &context, &r);
            blocked[i] = r.tfar == -inf ? 1 : 0;
        }
    }

    // Embree does not say how much memory its BVH takes; this is the geometry it copied.
    std::size_t memory_bytes() const override { return bytes_; }

private:
    // The course's rays are open intervals (tmin, tmax); Embree's are closed [tnear, tfar]. The ends are
    // nudged inwards by one ulp so both accept the same t.
    static RTCRayHit to_embree(const ray& r) {
        RTCRayHit rh{};
        rh.ray.org_x = r.org.x; rh.ray.org_y = r.org.y; rh.ray.org_z = r.org.z;
        rh.ray.dir_x = r.dir.x; rh.ray.dir_y = r.dir.y; rh.ray.dir_z = r.dir.z;
        rh.ray.tnear = std::nextafter(r.tmin, inf);
        rh.ray.tfar = r.tmax == inf ? inf : std::nextafter(r.tmax, -inf);
        rh.ray.mask = 0xFFFFFFFFu;
        rh.ray.flags = 0;
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

    embree_config config_;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::size_t bytes_ = 0;
};

}  // namespace

bool embree_available() { return true; }

std::unique_ptr<accel> make_embree_accel(const embree_config& config) { return std::make_unique<embree_accel>(config); }

}  // namespace strahl::race

#endif
