// Every combination of chapter 15's triangle tests and box tests, instantiated once.
#include "strahl/ch15/accel.hpp"

namespace strahl::ch15 {

namespace {
template <test_kind K>
std::unique_ptr<accel> tree_with(box_kind b) {
    switch (b) {
        case box_kind::plain: return std::make_unique<robust_bvh<K, box_kind::plain>>();
        case box_kind::conservative: return std::make_unique<robust_bvh<K, box_kind::conservative>>();
        case box_kind::fast: return std::make_unique<robust_bvh<K, box_kind::fast>>();
    }
    return nullptr;
}
}  // namespace

std::unique_ptr<accel> make_tree(test_kind k, box_kind b) {
    switch (k) {
        case test_kind::mt: return tree_with<test_kind::mt>(b);
        case test_kind::mt_epsilon: return tree_with<test_kind::mt_epsilon>(b);
        case test_kind::mt_edges: return tree_with<test_kind::mt_edges>(b);
        case test_kind::watertight: return tree_with<test_kind::watertight>(b);
        case test_kind::watertight_double: return tree_with<test_kind::watertight_double>(b);
    }
    return nullptr;
}

std::unique_ptr<accel> make_brute(test_kind k) {
    switch (k) {
        case test_kind::mt: return std::make_unique<brute_tests<test_kind::mt>>();
        case test_kind::mt_epsilon: return std::make_unique<brute_tests<test_kind::mt_epsilon>>();
        case test_kind::mt_edges: return std::make_unique<brute_tests<test_kind::mt_edges>>();
        case test_kind::watertight: return std::make_unique<brute_tests<test_kind::watertight>>();
        case test_kind::watertight_double: return std::make_unique<brute_tests<test_kind::watertight_double>>();
    }
    return nullptr;
}

}  // namespace strahl::ch15
