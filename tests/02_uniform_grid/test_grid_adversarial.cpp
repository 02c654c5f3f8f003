// Chapter 02's grid against brute force on the cases that break grids (no points: they need every
// exercise done). Every answer must equal brute force bit for bit: t, primitive id, u and v.
#include "strahl/ch02/accel.hpp"
#include "strahl/procedural.hpp"
#include "strahl/rng.hpp"
#include <catch2/catch.hpp>
#include <bit>
#include <cmath>
#include <numeric>

using namespace strahl;
using namespace strahl::ch02;

namespace {

constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();

// Brute force, far origins moved to the scene by the frame as the grid's queries are (ray_frame.hpp).
hit brute_closest(const ch01::triangle_set& set, const ray_frame& f, const ray& query) {
    return f.closest(query, [&](ray r) {
        hit best;
        for (std::uint32_t i = 0; i < set.size(); ++i) set.intersect(i, r, best);
        return best;
    });
}
bool brute_any(const ch01::triangle_set& set, const ray_frame& f, const ray& query) {
    return f.any(query, [&](const ray& r) {
        for (std::uint32_t i = 0; i < set.size(); ++i)
            if (set.occludes(i, r)) return true;
        return false;
    });
}
bool identical(const hit& a, const hit& b) {
    return std::bit_cast<std::uint32_t>(a.t) == std::bit_cast<std::uint32_t>(b.t) && a.prim == b.prim &&
           std::bit_cast<std::uint32_t>(a.u) == std::bit_cast<std::uint32_t>(b.u) &&
           std::bit_cast<std::uint32_t>(a.v) == std::bit_cast<std::uint32_t>(b.v);
}

// Rays from around the scene towards random points of its box, some starting inside it, some with a short
// tmax, and rays along the axes exactly on cell boundaries (with +0 and -0 components).
std::vector<ray> rays_for(const triangle_mesh& mesh, const grid_dims& g, std::size_t n) {
    std::vector<ray> rays;
    aabb b = mesh.bounds();
    if (b.is_empty()) b = aabb{vec3(-1), vec3(1)};
    const vec3 c = b.centroid(), e = glm::max(b.extent(), vec3(1e-3f));
    pcg32 rng(7);
    const auto in_box = [&] { return b.min + vec3(rng.next_float(), rng.next_float(), rng.next_float()) * e; };
    for (std::size_t i = 0; i < n; ++i) {
        const vec3 target = in_box();
        const vec3 org = i % 3 == 0 ? in_box() : c + 2.0f * e * (vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f) * 2.0f;
        ray r{org, target - org};
        if (i % 7 == 0) r.tmax = rng.next_float() * 1.5f;
        if (i % 11 == 0) r.tmin = rng.next_float() * 0.5f;
        rays.push_back(r);
    }
    for (int k = 0; k <= g.res.x && k < 12; ++k)
        for (int a = 0; a < 3; ++a) {
            // On the k-th boundary of axis a, and on a boundary of axis (a+1)%3 too: along axis (a+2)%3.
            vec3 org = c;
            org[a] = g.box.min[a] + float(std::min(k, g.res[a])) * g.cell_size[a];
            const int b1 = (a + 1) % 3, along = (a + 2) % 3;
            org[b1] = g.box.min[b1] + float(g.res[b1] / 2) * g.cell_size[b1];
            org[along] = g.box.min[along] - e[along];
            vec3 d(0.0f);
            d[along] = 1.0f;
            d[a] = k % 2 ? -0.0f : 0.0f;
            rays.push_back(ray{org, d});
            org[along] = g.box.max[along] + e[along];
            d[along] = -2.0f;
            rays.push_back(ray{org, d});
        }
    return rays;
}

void check_against_brute_force(const scene& s, const grid_options& opt, std::size_t n = 600) {
    const ch01::triangle_set set(s.mesh);
    for (const bool virt : {false, true}) {
        const auto acc = make_accel(virt, opt);
        acc->build(s);
        const grid_dims g = virt ? dynamic_cast<grid_accel<ch01::object_set>&>(*acc).grid().dims()
                                 : dynamic_cast<grid_accel<ch01::triangle_set>&>(*acc).grid().dims();
        std::vector<ray> rays = rays_for(s.mesh, g, n);
        rays.push_back(ray{vec3(nan_f), vec3(1, 0, 0)});
        rays.push_back(ray{vec3(0), vec3(nan_f, 1, 0)});
        rays.push_back(ray{vec3(0), vec3(0.0f)});
        rays.push_back(ray{vec3(0), vec3(1, 1, 1), 2.0f, 1.0f});
        std::vector<hit> hits(rays.size()), counted(rays.size());
        std::vector<std::uint8_t> blocked(rays.size());
        acc->intersect(rays, hits);
        acc->occluded(rays, blocked);
        const auto c = acc->intersect_counted(rays, counted);
        REQUIRE(c.has_value());
        CHECK(c->rays == rays.size());
        std::size_t wrong = 0, found = 0;
        const ray_frame frame(s.mesh.bounds());
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const hit want = brute_closest(set, frame, rays[i]);
            found += want.found();
            const bool want_any = brute_any(set, frame, rays[i]);
            if (!identical(hits[i], want) || !identical(counted[i], want) || (blocked[i] != 0) != want_any) {
                const ray& r = rays[i];
                if (++wrong < 5)
                    UNSCOPED_INFO("ray " << i << " from (" << r.org.x << ", " << r.org.y << ", " << r.org.z
                                  << ") along (" << r.dir.x << ", " << r.dir.y << ", " << r.dir.z << "), t in ["
                                  << r.tmin << ", " << r.tmax << "]: got t " << hits[i].t << " prim " << hits[i].prim
                                  << " u " << hits[i].u << " v " << hits[i].v << " (counted: t " << counted[i].t
                                  << " prim " << counted[i].prim << "), occluded " << int(blocked[i] != 0)
                                  << "; brute force t " << want.t << " prim " << want.prim << " u " << want.u
                                  << " v " << want.v << ", occluded " << int(want_any));
            }
        }
        INFO(s.name << ", " << (virt ? "virtual" : "triangles") << ", lambda " << opt.lambda << ", cells "
                    << g.cell_count() << ", " << found << " of " << rays.size() << " rays hit");
        CHECK(wrong == 0);
        if (s.mesh.triangle_count() > 0 && rays.size() > 50) CHECK(found > 0);
    }
}

scene from_mesh(const std::string& name, triangle_mesh m) { return mesh_scene(name, std::move(m)); }

triangle_mesh flat_mesh() {  // a 10 x 10 patch of triangles in the plane z = 0.5
    triangle_mesh m;
    for (int j = 0; j <= 10; ++j)
        for (int i = 0; i <= 10; ++i) m.positions.push_back(vec3(float(i) * 0.1f, float(j) * 0.1f, 0.5f));
    for (std::uint32_t j = 0; j < 10; ++j)
        for (std::uint32_t i = 0; i < 10; ++i) {
            const std::uint32_t a = j * 11 + i;
            m.indices.push_back(uvec3(a, a + 1, a + 12));
            m.indices.push_back(uvec3(a, a + 12, a + 11));
        }
    return m;
}

}  // namespace

TEST_CASE("ch02 grid: equals brute force on the teapot and a triangle soup, both primitive sets", "[ch02][adversarial]") {
    check_against_brute_force(from_mesh("teapot", teapot_mesh(3)), {});
    check_against_brute_force(from_mesh("soup", random_soup(800, 3, 0.1f)), {});
    grid_options exact;
    exact.exact_overlap = true;
    check_against_brute_force(from_mesh("teapot exact", teapot_mesh(3)), exact);
}

TEST_CASE("ch02 grid: huge and tiny lambda, all triangles in one cell", "[ch02][adversarial]") {
    for (const float lambda : {0.0001f, 0.5f, 64.0f}) {
        grid_options opt;
        opt.lambda = lambda;
        check_against_brute_force(from_mesh("teapot", teapot_mesh(2)), opt, 300);
    }
    grid_options capped;
    capped.lambda = 1e6f;
    capped.max_cells = 200000;
    check_against_brute_force(from_mesh("soup", random_soup(200, 5, 0.2f)), capped, 300);
    // One cell holds everything.
    const auto acc = make_accel(false, grid_options{0.0001f});
    acc->build(from_mesh("teapot", teapot_mesh(2)));
    CHECK(dynamic_cast<grid_accel<ch01::triangle_set>&>(*acc).grid().dims().cell_count() == 1);
}

TEST_CASE("ch02 grid: flat scene, one triangle, copies of one triangle, empty scene", "[ch02][adversarial]") {
    check_against_brute_force(from_mesh("flat", flat_mesh()), {});
    triangle_mesh one;
    one.positions = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)};
    one.indices = {uvec3(0, 1, 2)};
    check_against_brute_force(from_mesh("one", one), {});
    triangle_mesh copies = one;
    for (int i = 1; i < 300; ++i) copies.indices.push_back(uvec3(0, 1, 2));
    check_against_brute_force(from_mesh("copies", copies), {}, 200);
    // The flat axis gets one cell of non-zero size.
    const auto acc = make_accel(false);
    acc->build(from_mesh("flat", flat_mesh()));
    const grid_dims g = dynamic_cast<grid_accel<ch01::triangle_set>&>(*acc).grid().dims();
    CHECK(g.res.z == 1);
    CHECK(g.cell_size.z > 0.0f);
    CHECK(g.res.x > 1);
    // Empty: no cells, every ray misses.
    const auto none = make_accel(true);
    none->build(scene{});
    std::vector<ray> rays{ray{vec3(0), vec3(1, 0, 0)}, ray{vec3(nan_f), vec3(nan_f)}};
    std::vector<hit> hits(2);
    std::vector<std::uint8_t> blocked(2, 7);
    none->intersect(rays, hits);
    none->occluded(rays, blocked);
    CHECK(!hits[0].found());
    CHECK(!hits[1].found());
    CHECK(blocked[0] == 0);
    CHECK(blocked[1] == 0);
}

TEST_CASE("ch02 grid: cell storage holds every triangle in the cells of its box", "[ch02][adversarial]") {
    const triangle_mesh m = teapot_mesh(2);
    const ch01::triangle_set set(m);
    uniform_grid grid;
    grid_options opt;
    grid.build(set, opt);
    const grid_dims& g = grid.dims();
    const grid_cells& c = grid.cells();
    CHECK(double(g.cell_count()) == Approx(opt.lambda * double(m.triangle_count())).epsilon(0.5));
    REQUIRE(c.offsets.size() == std::size_t(g.cell_count()) + 1);
    CHECK(c.offsets.front() == 0);
    CHECK(c.offsets.back() == c.prims.size());
    CHECK(std::is_sorted(c.offsets.begin(), c.offsets.end()));
    std::vector<int> seen(set.size(), 0);
    for (std::uint32_t p : c.prims) ++seen[p];
    CHECK(std::count(seen.begin(), seen.end(), 0) == 0);
    const grid_stats s = occupancy(g, c, set.size());
    CHECK(s.references == c.prims.size());
    CHECK(s.references_per_prim >= 1.0);
    // The references by log2 of their cell's count: they add up, and each bin holds what its cells hold.
    REQUIRE(s.refs_by_log2.size() == 16);
    std::vector<std::size_t> expect(16, 0);
    for (std::size_t i = 0; i + 1 < c.offsets.size(); ++i) {
        const std::size_t k = c.offsets[i + 1] - c.offsets[i];
        std::size_t b = 0;
        while (b < 15 && (std::size_t(2) << b) <= k) ++b;
        if (k > 0) expect[b] += k;
    }
    CHECK(s.refs_by_log2 == expect);
    CHECK(std::accumulate(s.refs_by_log2.begin(), s.refs_by_log2.end(), std::size_t(0)) == s.references);
}

namespace {
// n long thin triangles, each from one corner region of the unit cube to the opposite one: every box spans
// nearly the whole scene, so each triangle falls in nearly every cell.
triangle_mesh spanning_triangles(std::size_t n) {
    triangle_mesh m;
    pcg32 rng(11);
    for (std::size_t i = 0; i < n; ++i) {
        const vec3 a(0.01f * rng.next_float(), 0.01f * rng.next_float(), 0.01f * rng.next_float());
        const vec3 b = vec3(1.0f) - a;
        const std::uint32_t k = std::uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), {a, b, b + vec3(0.0f, 0.001f, 0.0f)});
        m.indices.push_back(uvec3(k, k + 1, k + 2));
    }
    return m;
}
}  // namespace

TEST_CASE("ch02 grid: triangles spanning the scene stay within the reference budget, still exact",
          "[ch02][adversarial]") {
    // Without the bound, 4,000 spanning triangles at 4 cells per triangle make about 4,000 x 16,000 = 64 M
    // references; the budget here is 1 M, so the build must lower the resolution and say so.
    const triangle_mesh m = spanning_triangles(4000);
    grid_options opt;
    opt.max_references = std::uint64_t(1) << 20;
    uniform_grid g;
    const ch01::triangle_set set(m);
    g.build(set, opt);
    CHECK(g.resolution_lowered());
    CHECK(g.cells().prims.size() <= opt.max_references);
    CHECK(count_references(g.dims(), std::vector<aabb>{aabb{vec3(0), vec3(1)}}) == std::uint64_t(g.dims().cell_count()));
    check_against_brute_force(from_mesh("spanning", spanning_triangles(600)), opt, 300);
    // 30,000 spanning triangles (about 3.6 * 10^9 references unbounded: a crash before the bound existed).
    const triangle_mesh big = spanning_triangles(30000);
    opt.max_references = std::uint64_t(1) << 22;
    uniform_grid g2;
    g2.build(ch01::triangle_set(big), opt);
    CHECK(g2.resolution_lowered());
    CHECK(g2.cells().prims.size() <= opt.max_references);
}

TEST_CASE("ch02 grid: 200,000 copies of one triangle build within the budget, a budget below their count is refused",
          "[ch02][adversarial]") {
    triangle_mesh m;
    m.positions = {vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)};
    m.indices.assign(200000, uvec3(0, 1, 2));
    grid_options opt;
    opt.max_references = std::uint64_t(1) << 22;
    uniform_grid g;
    g.build(ch01::triangle_set(m), opt);
    CHECK(g.cells().prims.size() <= opt.max_references);
    CHECK(g.resolution_lowered());
    opt.max_references = 1000;  // fewer than the triangles: even one cell cannot hold them
    uniform_grid refused;
    CHECK_THROWS_WITH(refused.build(ch01::triangle_set(m), opt), Catch::Contains("200000 primitives exceed"));
    opt.max_references = std::uint64_t(1) << 32;
    CHECK_THROWS_WITH(refused.build(ch01::triangle_set(m), opt), Catch::Contains("below 2^32"));
}
