// Embree 3 as an accel (embree_tracer.hpp): with Embree where CMake found it, else a stub.
#include "strahl/ch14/embree_tracer.hpp"
#include <stdexcept>

#ifndef STRAHL_HAVE_EMBREE

namespace strahl::ch14 {
bool embree_available() { return false; }
std::unique_ptr<accel> make_embree_tracer() {
    throw std::runtime_error("this build has no Embree 3 (install libembree-dev: ./course setup)");
}
}  // namespace strahl::ch14

#else

#include "strahl/denormals.hpp"
#include <cmath>
#include <embree3/rtcore.h>

namespace strahl::ch14 {

namespace {

// The course's interval is open, (tmin, tmax); Embree's closed: its tfar one float below tmax.
void to_embree(const ray& r, RTCRay& e) {
    e.org_x = r.org.x, e.org_y = r.org.y, e.org_z = r.org.z, e.tnear = r.tmin;
    e.dir_x = r.dir.x, e.dir_y = r.dir.y, e.dir_z = r.dir.z, e.time = 0.0f;
    e.tfar = r.tmax == inf ? inf : std::nextafter(r.tmax, -inf);
    e.mask = 0xFFFFFFFFu, e.id = 0, e.flags = 0;
}

class embree_tracer final : public accel {
public:
    embree_tracer() : device_(rtcNewDevice(nullptr)) {
        if (!device_) throw std::runtime_error("Embree: rtcNewDevice failed");
    }
    ~embree_tracer() override {
        if (scene_) rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    std::string name() const override { return "embree-medium"; }
    bool exact() const override { return false; }
    std::size_t memory_bytes() const override { return bytes_; }  // the geometry copied (Embree's BVH unknown)

    void build(const scene& s) override {
        if (scene_) rtcReleaseScene(scene_);
        scene_ = rtcNewScene(device_);
        rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
        const triangle_mesh& m = s.mesh;
        if (m.triangle_count() > 0) {
            RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                   3 * sizeof(float), m.positions.size()));
            for (std::size_t i = 0; i < m.positions.size(); ++i)
                for (int k = 0; k < 3; ++k) v[3 * i + k] = m.positions[i][k];
            auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                      3 * sizeof(unsigned), m.triangle_count()));
            for (std::size_t i = 0; i < m.triangle_count(); ++i)
                for (int k = 0; k < 3; ++k) idx[3 * i + k] = m.indices[i][k];
            rtcCommitGeometry(g);
            rtcAttachGeometry(scene_, g);
            rtcReleaseGeometry(g);
        }
        rtcCommitScene(scene_);
        if (const RTCError e = rtcGetDeviceError(device_); e != RTC_ERROR_NONE)
            throw std::runtime_error("Embree: building the scene failed (error " + std::to_string(int(e)) + ")");
        bytes_ = m.positions.size() * 12 + m.triangle_count() * 12;
    }

    void intersect(std::span<const ray> rays, std::span<hit> hits) const override {
        const denormals_flushed flushed;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            RTCRayHit rh;
            to_embree(rays[i], rh.ray);
            rh.hit.geomID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene_, &context, &rh);
            const bool found = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            hits[i] = found ? hit{rh.ray.tfar, rh.hit.primID, rh.hit.u, rh.hit.v, invalid_id} : hit{};
        }
    }

    void occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const override {
        const denormals_flushed flushed;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            RTCRay r;
            to_embree(rays[i], r);
            rtcOccluded1(scene_, &context, &r);
            blocked[i] = r.tfar == -inf ? 1 : 0;  // Embree marks a blocked ray with tfar = -inf
        }
    }

private:
    RTCDevice device_;
    RTCScene scene_ = nullptr;
    std::size_t bytes_ = 0;
};

}  // namespace

bool embree_available() { return true; }
std::unique_ptr<accel> make_embree_tracer() { return std::make_unique<embree_tracer>(); }

}  // namespace strahl::ch14

#endif
