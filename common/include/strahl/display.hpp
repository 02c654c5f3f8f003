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

// Rasterises the mesh with the camera's image size. Throws std::runtime_error if OSMesa cannot start.
raster_result rasterize(const triangle_mesh& mesh, const camera& cam);

struct line_segment {
    vec3 a, b;
    color c{1.0f, 1.0f, 0.0f};
};

// Draws 3D line segments, seen through cam, over img (same size as the camera's image); no depth test.
void draw_lines(image& img, const camera& cam, const std::vector<line_segment>& lines, float width = 1.0f);

// The 12 edges of a box.
std::vector<line_segment> box_wireframe(const aabb& box, color c);

}  // namespace strahl
