// Embree 3 on chapter 15's escape test (embree_robust.hpp): with Embree where CMake found it, else a stub.
#include "strahl/ch15/embree_robust.hpp"
#include <stdexcept>

#ifndef STRAHL_HAVE_EMBREE

namespace strahl::ch15 {
bool embree_available() { return false; }
std::string embree_version() { return "not available"; }
std::vector<std::uint8_t> embree_found(const triangle_mesh&, std::span<const ray>, bool) {
    throw std::runtime_error("this build has no Embree 3 (install libembree-dev: ./course setup)");
}
}  // namespace strahl::ch15

#else

#include "strahl/parallel.hpp"
#include "strahl/denormals.hpp"
#include <embree3/rtcore.h>

namespace strahl::ch15 {

namespace {

void check(RTCDevice device, const char* what) {
    if (const RTCError e = rtcGetDeviceError(device); e != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("Embree: ") + what + " failed (error " + std::to_string(int(e)) + ")");
}

}  // namespace

bool embree_available() { return true; }

std::string embree_version() {
    return std::to_string(RTC_VERSION_MAJOR) + "." + std::to_string(RTC_VERSION_MINOR) + "." +
           std::to_string(RTC_VERSION_PATCH);
}

std::vector<std::uint8_t> embree_found(const triangle_mesh& m, std::span<const ray> rays, bool robust) {
    const denormals_flushed flushed;
    RTCDevice device = rtcNewDevice(nullptr);
    if (!device) throw std::runtime_error("Embree: rtcNewDevice failed");
    RTCScene scene = rtcNewScene(device);
    if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           3 * sizeof(float), m.positions.size()));
    for (std::size_t i = 0; i < m.positions.size(); ++i)
        for (int k = 0; k < 3; ++k) v[3 * i + k] = m.positions[i][k];
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                              3 * sizeof(unsigned), m.triangle_count()));
    for (std::size_t i = 0; i < m.triangle_count(); ++i)
        for (int k = 0; k < 3; ++k) idx[3 * i + k] = m.indices[i][k];
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);
    check(device, "building the scene");
    std::vector<std::uint8_t> out(rays.size());
    parallel_for_chunks(rays.size(), 4096, [&](std::size_t first, std::size_t last) {
        const denormals_flushed on_this_thread;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (std::size_t i = first; i < last; ++i) {
            const ray& r = rays[i];
            RTCRayHit rh{};
            rh.ray.org_x = r.org.x, rh.ray.org_y = r.org.y, rh.ray.org_z = r.org.z, rh.ray.tnear = r.tmin;
            rh.ray.dir_x = r.dir.x, rh.ray.dir_y = r.dir.y, rh.ray.dir_z = r.dir.z, rh.ray.tfar = r.tmax;
            rh.ray.mask = 0xFFFFFFFFu;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene, &context, &rh);
            out[i] = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? 1 : 0;
        }
    });
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return out;
}

}  // namespace strahl::ch15

#endif
