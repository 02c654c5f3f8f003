// Chapter 01's object-oriented tracer behind the accel interface: one heap object per triangle in a
// std::vector of owning pointers, a virtual intersect() call per triangle per ray. Same triangle test as
// brute force, reached through a virtual call: the race shows what the indirection costs.
#pragma once
#include "strahl/accel.hpp"
#include <memory>

namespace strahl::race {

std::unique_ptr<accel> make_oo_tracer();

}  // namespace strahl::race
