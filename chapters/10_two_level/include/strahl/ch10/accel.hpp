// Chapter 10's structures behind the course's accel interface: the two-level BVH ("ch10-two-level") and
// its exact reference, the instanced brute force ("ch10-brute-instanced"). Both trace a scene's instances
// (scene.instances) as they are, or a plain scene as one instance; both report flattened primitive ids and
// the instance in hit.inst. The race registers them.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch10/two_level.hpp"
#include <memory>

namespace strahl::ch10 {

// The accel with access to its structure (the program and the tests update it between frames).
class two_level_accel_base : public strahl::accel {
public:
    virtual two_level& structure() = 0;
};
std::unique_ptr<two_level_accel_base> make_accel(two_level_config config = default_config());
std::unique_ptr<strahl::accel> make_brute_accel();

}  // namespace strahl::ch10
