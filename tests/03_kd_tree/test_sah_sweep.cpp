// Exercise 03.1 SAH event sweep (8 points). Only split_cost and sah_sweep, on hand-made event lists in the
// box [0, 4] x [0, 1] x [0, 1] (surface area 18; a plane at x = p leaves areas 2 (p + 1 + p) and
// 2 ((4 - p) + 1 + (4 - p))).
#include "strahl/ch03/sah.hpp"
#include <catch2/catch.hpp>
#include <vector>

using namespace strahl;
using namespace strahl::ch03;

namespace {
const aabb box_x{vec3(0, 0, 0), vec3(4, 1, 1)};
const sah_params unit{1.0f, 1.0f, 0.0f};  // C_T = 1, C_I = 1, no empty bonus
event s(float p) { return {p, event_type::start}; }
event e(float p) { return {p, event_type::end}; }
event pl(float p) { return {p, event_type::planar}; }
}  // namespace

TEST_CASE("03.1 SAH event sweep: the cost of one plane, with C_T, C_I and the empty bonus", "[ch03][pts:2]") {
    // x = 1: P_L = 6/18, P_R = 14/18.
    CHECK(split_cost(box_x, 0, 1.0f, 2, 3, sah_params{1.0f, 1.5f, 0.2f}) == Approx(1.0 + 1.5 * (12.0 + 42.0) / 18.0));
    CHECK(split_cost(box_x, 0, 1.0f, 2, 3, sah_params{2.0f, 1.0f, 0.0f}) == Approx(2.0 + 54.0 / 18.0));
    // One side empty: the bonus discounts the whole cost; without a bonus it does not.
    CHECK(split_cost(box_x, 0, 1.0f, 0, 3, sah_params{1.0f, 1.5f, 0.2f}) == Approx(0.8 * (1.0 + 1.5 * 42.0 / 18.0)));
    CHECK(split_cost(box_x, 0, 1.0f, 3, 0, sah_params{1.0f, 1.5f, 0.2f}) == Approx(0.8 * (1.0 + 1.5 * 18.0 / 18.0)));
    CHECK(split_cost(box_x, 0, 1.0f, 0, 3, unit) == Approx(1.0 + 42.0 / 18.0));
    // The same box standing on y: the axis decides which side shrinks.
    const aabb box_y{vec3(0, 0, 0), vec3(1, 4, 1)};
    CHECK(split_cost(box_y, 1, 3.0f, 1, 1, unit) == Approx(1.0 + (14.0 + 6.0) / 18.0));
    // A box without area (a point): no split can be evaluated.
    CHECK(split_cost(aabb{vec3(1), vec3(1)}, 0, 1.0f, 1, 1, unit) == inf);
}

TEST_CASE("03.1 SAH event sweep: finds the cheapest plane and its counts on a hand-made list", "[ch03][pts:3]") {
    // Three triangles in [0, 1] (two from 0, one from 0.5), one in [2, 4], one planar at x = 3.
    // Planes: 0.5 (N_L 2, N_R 5): 1 + 88/18; 1 (3, 2): 1 + 46/18; 2 (3, 2): 1 + 50/18;
    // 3 (planar: 4 + 1 | 1 or 4 | 1 + 1): 1 + 68/18. The best is x = 1.
    const std::vector<event> ev = {s(0), s(0), s(0.5f), e(1), e(1), e(1), s(2), pl(3), e(4)};
    const split_candidate c = sah_sweep(ev, 0, box_x, 5, unit);
    CHECK(c.axis == 0);
    CHECK(c.pos == 1.0f);
    CHECK(c.cost == Approx(1.0 + 46.0 / 18.0));
    CHECK(c.n_left == 3);
    CHECK(c.n_right == 2);
    CHECK(c.n_planar == 0);
    // With a large C_T nothing changes but the cost.
    const split_candidate d = sah_sweep(ev, 0, box_x, 5, sah_params{10.0f, 1.0f, 0.0f});
    CHECK(d.pos == 1.0f);
    CHECK(d.cost == Approx(10.0 + 46.0 / 18.0));
}

TEST_CASE("03.1 SAH event sweep: planar triangles go to the cheaper side, empty space is cut off",
          "[ch03][pts:3]") {
    // Two triangles in [0, 1] and one planar at x = 1, one in [3, 4]: at x = 1 the planar one is cheaper
    // on the left: 1 + (6 * 3 + 14 * 1)/18.
    const std::vector<event> left_ev = {s(0), s(0), e(1), e(1), pl(1), s(3), e(4)};
    const split_candidate a = sah_sweep(left_ev, 0, box_x, 4, unit);
    CHECK(a.pos == 1.0f);
    CHECK(a.planar_left);
    CHECK(a.n_left == 2);
    CHECK(a.n_right == 1);
    CHECK(a.n_planar == 1);
    CHECK(a.cost == Approx(1.0 + 32.0 / 18.0));
    // Mirrored: the planar one at x = 3 goes right.
    const std::vector<event> right_ev = {s(0), e(1), pl(3), s(3), s(3), e(4), e(4)};
    const split_candidate b = sah_sweep(right_ev, 0, box_x, 4, unit);
    CHECK(b.pos == 3.0f);
    CHECK_FALSE(b.planar_left);
    CHECK(b.n_left == 1);
    CHECK(b.n_right == 2);
    CHECK(b.n_planar == 1);
    CHECK(b.cost == Approx(1.0 + 32.0 / 18.0));
    // One triangle in [3, 4]: the plane x = 3 cuts off the empty left, discounted by the bonus.
    const std::vector<event> one = {s(3), e(4)};
    const split_candidate c = sah_sweep(one, 0, box_x, 1, sah_params{1.0f, 1.5f, 0.2f});
    CHECK(c.pos == 3.0f);
    CHECK(c.n_left == 0);
    CHECK(c.n_right == 1);
    CHECK(c.cost == Approx(0.8 * (1.0 + 1.5 * 6.0 / 18.0)));
    // Events only on the box's faces (or none at all): no plane strictly inside, cost inf.
    const std::vector<event> faces = {s(0), e(4), pl(4)};
    const split_candidate f = sah_sweep(faces, 2, box_x, 2, unit);
    CHECK(f.cost == inf);
    CHECK(f.axis == 2);
    CHECK(sah_sweep({}, 1, box_x, 0, unit).cost == inf);
}
