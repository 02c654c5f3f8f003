// Chapter 12's packet tracers (packet_accel.hpp), made by name, and the exercises' out-of-line entries.
//
// Included once, at the end of packet_tests.cpp (exercises 12.1 to 12.3), so that the walks are compiled in
// the same translation unit as the student's box test, frustum test and partition, and inline them.
#pragma once
#include "strahl/ch12/packet_accel.hpp"
#include <stdexcept>

namespace strahl::ch12 {

std::unique_ptr<packet_accel_base> make_accel(std::string name, const packet_config& c) {
    const int tile = c.tile_w * c.tile_h;
    if (c.tile_w < 1 || c.tile_h < 1 || tile % c.lanes != 0)
        throw std::invalid_argument("packet tracer: a " + std::to_string(c.tile_w) + "x" + std::to_string(c.tile_h) +
                                    " tile is no whole number of " + std::to_string(c.lanes) + "-lane vectors");
    const int vectors = tile / c.lanes;
    const auto key = [](walk_kind w, int k, int v) { return int(w) * 10000 + k * 100 + v; };
    using wk = walk_kind;
    switch (key(c.walk, c.lanes, vectors)) {
    case key(wk::masked, 4, 1): return std::make_unique<packet_accel<wk::masked, 4, 1>>(std::move(name), c);
    case key(wk::masked, 8, 1): return std::make_unique<packet_accel<wk::masked, 8, 1>>(std::move(name), c);
    case key(wk::masked, 16, 1): return std::make_unique<packet_accel<wk::masked, 16, 1>>(std::move(name), c);
    case key(wk::ranged, 16, 4): return std::make_unique<packet_accel<wk::ranged, 16, 4>>(std::move(name), c);
    case key(wk::ranged, 16, 16): return std::make_unique<packet_accel<wk::ranged, 16, 16>>(std::move(name), c);
    case key(wk::partition, 16, 4): return std::make_unique<packet_accel<wk::partition, 16, 4>>(std::move(name), c);
    case key(wk::partition, 16, 16): return std::make_unique<packet_accel<wk::partition, 16, 16>>(std::move(name), c);
    case key(wk::wide, 8, 1): return std::make_unique<packet_accel<wk::wide, 8, 1>>(std::move(name), c);
    case key(wk::wide, 16, 1): return std::make_unique<packet_accel<wk::wide, 16, 1>>(std::move(name), c);
    case key(wk::frustum, 16, 1): return std::make_unique<packet_accel<wk::frustum, 16, 1>>(std::move(name), c);
    default:
        throw std::invalid_argument(std::string("packet tracer: the ") + to_string(c.walk) + " walk is not built for " +
                                    std::to_string(c.lanes) + " lanes and " + std::to_string(c.tile_w) + "x" +
                                    std::to_string(c.tile_h) + " tiles (built: masked 2x2/4, 4x2/8, 4x4/16; ranged and "
                                    "partition 8x8 or 16x16 with 16 lanes; wide 4x2/8, 4x4/16; frustum 4x4/16)");
    }
}

}  // namespace strahl::ch12

namespace strahl::ch12 {

// Out-of-line entries to the three exercises for the tests, which call them on their own (the exercises
// themselves are forced inline into the walks).
template <bool Coherent, int K>
simd::vmask<K> packet_box_out_of_line(const lane_rays<K>& r, const float* bmin, const float* bmax, int octant,
                                      simd::vfloat<K>& entry) {
    return packet_box<Coherent>(r, bmin, bmax, octant, entry);
}
template <int K, int V>
bool frustum_misses_out_of_line(const ray_packet<K, V>& p, const float* bmin, const float* bmax) {
    return frustum_misses(p, bmin, bmax);
}
int partition_out_of_line(std::uint16_t* ids, int count, const std::vector<unsigned>& bits) {
    return partition_active<16>(ids, count, [&](int at) { return bits.at(std::size_t(at / 16)); });
}
template simd::vmask<8> packet_box_out_of_line<true, 8>(const lane_rays<8>&, const float*, const float*, int, simd::vfloat<8>&);
template simd::vmask<8> packet_box_out_of_line<false, 8>(const lane_rays<8>&, const float*, const float*, int, simd::vfloat<8>&);
template simd::vmask<16> packet_box_out_of_line<true, 16>(const lane_rays<16>&, const float*, const float*, int, simd::vfloat<16>&);
template simd::vmask<16> packet_box_out_of_line<false, 16>(const lane_rays<16>&, const float*, const float*, int, simd::vfloat<16>&);
template bool frustum_misses_out_of_line<16, 1>(const ray_packet<16, 1>&, const float*, const float*);
template bool frustum_misses_out_of_line<16, 4>(const ray_packet<16, 4>&, const float*, const float*);

}  // namespace strahl::ch12
