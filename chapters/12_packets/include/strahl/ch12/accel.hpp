// Chapter 12's packet tracers behind the course's accel interface: chapter 05's binned SAH tree (or chapter
// 13's 8-wide tree collapsed from it) walked by packets of rays formed from tiles of the batch. The race
// registers them; the chapter's program and tests also read their lane utilisation.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch04/accel.hpp"
#include "strahl/stats.hpp"
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace strahl::ch12 {

enum class walk_kind {
    masked,     // K rays, chapter 05's binary tree, the active mask (Wald et al. 2001)
    ranged,     // V x K rays, binary tree, first active vector and frustum (Wald, Boulos and Shirley 2007)
    partition,  // V x K rays, binary tree, active-ray list partitioned per node (Overbeck et al. 2008)
    wide,       // K rays, chapter 13's 8-wide tree: K rays against each child box (Embree's hybrid kernels)
    frustum,    // V x K rays, 8-wide tree, the packet's frustum against all children at once, rays at the
                // leaves (Embree's coherent kernels); packets of mixed octants take the wide walk
};
const char* to_string(walk_kind w);

struct packet_config {
    walk_kind walk = walk_kind::wide;
    int lanes = 16;             // K: rays per SIMD vector, 4, 8 or 16
    int tile_w = 4, tile_h = 4; // the rays of one packet: a tile_w x tile_h tile (tile_w * tile_h = V * K)
    // The batch's rays seen as rows of this many (the race's image width: primary rays are pixels in
    // scanline order, secondary rays follow their primary hits in pixel order); 0: packets of consecutive rays.
    int image_width = 0;
    // The binary tree the walks start from (collapsed for the wide walks): empty for chapter 05's binned SAH
    // tree (16 bins), else a builder handed the mesh (chapter 16's registry passes chapter 09's SBVH).
    ch04::mesh_bvh_builder builder{};
};

// One line: "wide walk, 16 lanes, 4x4 tiles".
std::string describe(const packet_config& c);

// What the program and the tests read beside the interface: the packets' lane utilisation.
struct lane_stats {
    counter_values counts;               // node visits are per packet; box and triangle tests per active lane
    // visits[k]: vector visits with k of the K lanes active, k = 0..K; a vector visit is one vector of K rays
    // tested at a node (one per node visit where the packet is one vector; large packets test several)
    std::vector<std::uint64_t> visits;
    std::uint64_t packets = 0;
    double mean_active() const;          // active lanes per vector visit
};

class packet_accel_base : public accel {
public:
    virtual const packet_config& config() const = 0;
    // The queries, counting lanes; per_ray (optional, one entry per ray) receives the mean fraction of active
    // lanes over the node visits of the packet that traced the ray (-1 for rays traced alone).
    virtual lane_stats closest_lanes(std::span<const ray> rays, std::span<hit> hits, std::vector<float>* per_ray) const = 0;
    virtual lane_stats any_lanes(std::span<const ray> rays, std::span<std::uint8_t> blocked,
                                 std::vector<float>* per_ray) const = 0;
};

// The combinations built (a packet tracer is compiled per walk, K and V): masked K = 4 (2x2), 8 (4x2), 16
// (4x4); ranged and partition K = 16 with 8x8 or 16x16 tiles; wide K = 8 (4x2), 16 (4x4); frustum K = 16
// with 4x4 tiles. Throws
// std::invalid_argument for another.
std::unique_ptr<packet_accel_base> make_accel(std::string name, const packet_config& config);

// The packets of a batch of n rays: calls f(ids, count) per packet with the batch indices of its rays (count
// <= tile_w * tile_h; lane i holds ray ids[i]). Tiles of rows of `image_width` rays, where the batch holds
// whole rows; the rays past the last whole row, or all of them when image_width is 0 or narrower than a
// tile, in packets of consecutive rays. Where the batch's last rows are fewer than a tile's height, their
// tiles are wider by as much (a thread's chunk of a small ray set may hold one row: tiles of 16 x 1, not
// 4 x 1). A tile cut by the image's right edge is a partial packet.
template <class F>
void for_each_packet(std::size_t n, const packet_config& c, F&& f) {
    const std::size_t size = std::size_t(c.tile_w) * std::size_t(c.tile_h);
    std::uint32_t ids[256];
    std::size_t rows_end = 0;
    if (c.image_width >= c.tile_w && c.image_width > 0) {
        const std::size_t w = std::size_t(c.image_width), rows = n / w;
        rows_end = rows * w;
        for (std::size_t y = 0; y < rows; y += std::size_t(c.tile_h)) {
            // A band of fewer rows than a tile (the batch's last): tiles as much wider as the lanes allow.
            const std::size_t h = std::min(std::size_t(c.tile_h), rows - y);
            const std::size_t tw = std::max(std::size_t(c.tile_w), size / h);
            for (std::size_t x = 0; x < w; x += tw) {
                int count = 0;
                for (std::size_t dy = 0; dy < h; ++dy)
                    for (std::size_t dx = 0; dx < tw && x + dx < w; ++dx)
                        ids[count++] = std::uint32_t((y + dy) * w + x + dx);
                f(ids, count);
            }
        }
    }
    for (std::size_t i = rows_end; i < n; i += size) {
        int count = 0;
        for (std::size_t k = i; k < n && k < i + size; ++k) ids[count++] = std::uint32_t(k);
        f(ids, count);
    }
}

}  // namespace strahl::ch12
