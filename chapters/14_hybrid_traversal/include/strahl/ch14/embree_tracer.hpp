// Embree 3 behind the course's accel interface, for chapter 14's flight: its BVH at medium build quality, one
// ray per call (rtcIntersect1, rtcOccluded1), as chapter 13's tree is called by the single-ray renderer.
// Compiled with Embree where CMake found it (STRAHL_HAVE_EMBREE); elsewhere embree_available() is false and
// make_embree_tracer throws. (The race's own Embree rows, with packets and streams: chapters/16_race.)
#pragma once
#include "strahl/accel.hpp"
#include <memory>

namespace strahl::ch14 {

bool embree_available();

// Named "embree-medium". build() copies the mesh into Embree; hits carry Embree's t, primID, u and v. Not
// exact (Embree's own triangle test): its images may differ from the course's in a few pixels.
std::unique_ptr<accel> make_embree_tracer();

}  // namespace strahl::ch14
