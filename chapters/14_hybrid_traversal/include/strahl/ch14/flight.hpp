// The setting of chapter 14's flight (the program's third part): a camera path through a scene, and its floor
// made a mirror, so that the Whitted renderer sends a reflection ray from every pixel that sees the floor.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/camera.hpp"
#include "strahl/scene.hpp"

namespace strahl::ch14 {

// The camera at frame f of n (n >= 1) flying through `box`: along its longest horizontal axis (x or z) from
// 15% to 65% of it (Sponza: from under the gallery at one end through the open atrium), the eye at
// 25% of the height over the middle of the other axis, looking ahead and a little down, swinging gently (up
// to 12 degrees) to each side and back; 60 degrees vertical field of view.
camera_desc flight_camera(const aabb& box, int f, int n);

// The floor made a mirror (a material of kind mirror added): the triangles whose unit normal has |y| > 0.9 and
// whose centroid lies within 2% of the scene's height of the floor, the lowest surface that rays straight
// down from the flight's path hit (the box's lowest y where they hit none). Not the scene's lowest triangles:
// Sponza's lie 12 units under its floor, never seen. `built`: a structure built over s.mesh. Returns the
// number of mirror triangles.
std::size_t make_floor_mirror(scene& s, const accel& built);

}  // namespace strahl::ch14
