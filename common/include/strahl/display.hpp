// The rasteriser (OSMesa, off-screen OpenGL in software): an independent oracle for primary visibility and
// the way the course draws overlays. It uses the tracer's camera with the same pixel centres (camera.hpp),
// so the triangle-id buffer names the triangle a primary ray through each pixel centre should hit.
#pragma once
#include "strahl/camera.hpp"
#include "strahl/image.hpp"
#include "strahl/scene.hpp"
#include <cstdint>
#include <vector>

namespace strahl {

struct raster_result {
    int width = 0, height = 0;
    image colour;                     // flat-shaded by facing ratio, for looking at
    std::vector<std::uint32_t> ids;   // triangle id per pixel, invalid_id where no triangle covers it
    std::vector<float> depth;         // distance from the eye along the pixel-centre ray; inf where empty
};

// Rasterises the mesh with the camera's image size. Throws std::runtime_error if OSMesa cannot start or a
// triangle names a vertex that does not exist. Triangles with non-finite vertices are left out. Geometry
// closer to the eye than 1e-6 of the far distance is clipped by the near plane and missing from ids; depth
// comes from a 24-bit depth buffer with znear pushed out as far as nothing visible is clipped, so it is
// good to about 1e-4 relative or better, coarser when geometry comes very close to the eye.
raster_result rasterize(const triangle_mesh& mesh, const camera& cam);

struct line_segment {
    vec3 a, b;
    color c{1.0f, 1.0f, 0.0f};
};

// Draws 3D line segments, seen through cam, over img (same size as the camera's image, else
// std::invalid_argument); no depth test, later segments on top, no antialiasing. Covered pixels take the
// segment's colour exactly (linear, may exceed 1). Segments reaching behind the eye are clipped.
void draw_lines(image& img, const camera& cam, const std::vector<line_segment>& lines, float width = 1.0f);

// The 12 edges of a box.
std::vector<line_segment> box_wireframe(const aabb& box, color c);

}  // namespace strahl
