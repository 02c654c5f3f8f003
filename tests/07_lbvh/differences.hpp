// Comparing long arrays in chapter 07's tests: the first index where two differ, so that a failure prints
// one number rather than two arrays of 10^5 entries (which Catch2 would spend minutes printing).
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

namespace strahl::test {

// The first index where a and b differ (the shorter length where one is a prefix of the other); -1 where
// they are equal.
template <class T>
std::ptrdiff_t first_difference(const std::vector<T>& a, const std::vector<T>& b) {
    const auto [pa, pb] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
    if (pa == a.end() && pb == b.end()) return -1;
    return pa - a.begin();
}

}  // namespace strahl::test
