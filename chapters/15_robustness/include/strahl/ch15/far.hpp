// Chapter 15's far-away experiment (main.cpp's section 2b): the teapot (about 6 units) seen from 1e3 to 1e7
// units, a field of view framing it, so that the rays' origins lie far outside every box and grazing rays meet
// its silhouette. Each test in the fast walk against brute force with the same test, closest hits bit for
// bit, with the rays' origins kept where they are and moved to the scene (ray_frame.hpp: what every
// structure does). Kept, Moeller-Trumbore's s = org - v0 carries the origin's rounding into u and v: its
// triangles accept rays passing beside them (the hits column grows), which brute force finds and the tree's
// boxes cull.
#pragma once
#include <string>

namespace strahl::ch15 {

// far.csv's text (distance, test, origins, rays, hits, unlike_brute_force), each row also printed; quick: 32 x
// 24 rays per distance instead of 320 x 240.
std::string run_far(bool quick);

}  // namespace strahl::ch15
