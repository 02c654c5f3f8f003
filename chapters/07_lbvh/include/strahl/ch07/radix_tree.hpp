// The hierarchy over sorted Morton codes: a binary radix tree, whose every inner node splits its range of
// sorted codes where their highest differing bit flips from 0 to 1. Two ways to find it:
//   the lecture's, top down: split [first, last] at the first (highest) bit where codes[first] and
//     codes[last] differ, found by binary search (Lauterbach et al. 2009); a range of equal codes is split
//     at its middle by index;
//   Karras's, every inner node at once: inner node i is found from i's neighbours alone, in parallel
//     (T. Karras, "Maximizing parallelism in the construction of BVHs, octrees, and k-d trees", HPG 2012,
//     section 4). Equal codes are told apart by their index: delta compares (code, index) pairs.
// Both number the nodes as Karras does: n leaves 0..n-1 (the sorted primitives), n - 1 inner nodes 0..n-2,
// inner node 0 the root; an inner node that splits after leaf g has its left child at index g (leaf g if
// the left range is that one leaf, else inner node g) and its right child at index g + 1 (likewise). Every
// inner node thus has one end of its range as its index, and the two forms are the same arrays wherever
// they build the same tree (they do when no two codes are equal).
#pragma once
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

namespace strahl::ch07 {

// A child reference: an inner node's index, or a leaf's with leaf_bit set.
inline constexpr std::uint32_t leaf_bit = 0x80000000u;
inline bool is_leaf_ref(std::uint32_t ref) { return (ref & leaf_bit) != 0; }

struct radix_tree {
    // Per inner node (n - 1 of them): children, the parent (root: none), the range of leaves [first, last].
    std::vector<std::uint32_t> left, right, parent, first, last;
    std::vector<std::uint32_t> leaf_parent;  // per leaf (n): its parent inner node (n == 1: none)
    static constexpr std::uint32_t none = 0xffffffffu;

    std::size_t leaves() const { return leaf_parent.size(); }
    void resize(std::size_t n_leaves);  // n_leaves - 1 inner nodes (none for n_leaves <= 1)
};

// Exercise 07.3 "the split search": the split of the range [first, last] (first < last) of sorted codes,
// the lecture's way: the last index of the left half. Where codes[first] != codes[last], their common
// prefix is std::countl_zero(codes[first] ^ codes[last]) bits long, and the split is the last index g in
// [first, last) whose code shares a longer prefix with codes[first]: codes[first..g] have the first
// differing bit 0, codes[g+1..last] have it 1. Found by binary search over [first, last), not a linear
// scan. Where codes[first] == codes[last] (the whole range is equal), the middle: (first + last) / 2.
std::uint32_t find_split(std::span<const std::uint64_t> codes, std::uint32_t first, std::uint32_t last);

// Karras's delta(i, j): the length of the common prefix of (codes[i], i) and (codes[j], j), as 64 + 32
// bits: countl_zero of the codes' xor, or for equal codes 64 + countl_zero of the indices' xor; -1 where j
// lies outside [0, n). (delta(i, j) with i == j never occurs.)
inline int karras_delta(std::span<const std::uint64_t> codes, std::int64_t i, std::int64_t j) {
    if (j < 0 || j >= std::int64_t(codes.size())) return -1;
    const std::uint64_t x = codes[std::size_t(i)] ^ codes[std::size_t(j)];
    if (x != 0) return std::countl_zero(x);
    return 64 + std::countl_zero(std::uint32_t(i) ^ std::uint32_t(j));
}

// The lecture's form, top down from the root; the two halves of large ranges as parallel tasks (TBB).
void build_radix_tree_lecture(std::span<const std::uint64_t> sorted_codes, radix_tree& out);

// Karras's form: every inner node independently, in parallel (TBB). Needs fewer than 2^31 codes.
void build_radix_tree_karras(std::span<const std::uint64_t> sorted_codes, radix_tree& out);

}  // namespace strahl::ch07
