// Chapter 15's structures as the race, strahl-trace and the program take them: any triangle test with any
// box test (robust_bvh.hpp), and brute force with any test, made by name or by kind. Each is compiled once,
// here, rather than in every file that names it.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch15/robust_bvh.hpp"
#include <memory>

namespace strahl::ch15 {

std::unique_ptr<accel> make_tree(test_kind k, box_kind b);  // named ch15-TEST-BOX, e.g. ch15-watertight-fast
std::unique_ptr<accel> make_brute(test_kind k);             // named brute-TEST, e.g. brute-watertight

}  // namespace strahl::ch15
