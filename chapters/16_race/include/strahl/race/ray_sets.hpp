// The race's ray sets are chapter 01's (strahl/ch01/ray_sets.hpp): the same primary, diffuse and shadow
// rays for every structure, in every program.
#pragma once
#include "strahl/ch01/ray_sets.hpp"

namespace strahl::race {

using ch01::is_any_hit;
using ch01::make_rays;
using ch01::parse_ray_kind;
using ch01::primary_rays;
using ch01::ray_kind;
using ch01::secondary_rays;
using ch01::to_string;
using ch01::trace_any;
using ch01::trace_closest;

}  // namespace strahl::race
