// Exercise 11.4, what one step buys: the prediction, the paired ratios with their verdict, and the counter
// that moved, on made-up race tables whose answers are known.
#include "strahl/ch11/step_report.hpp"
#include "strahl/ch11/steps.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

namespace step_report_test {

using strahl::race_csv_row;
using namespace strahl::ch11;

// A race.csv row: closest- and any-hit speeds, the counters (the same for both queries unless given).
race_csv_row row(const std::string& scene, const std::string& structure, const std::string& rays, double closest,
                 double any, double box = 10.0, double prim = 2.0, double nodes = 5.0, double memory = 1e6) {
    race_csv_row r;
    r.scene = scene, r.structure = structure, r.rays = rays, r.chapter = "11";
    r.closest_mrays_s = closest, r.any_mrays_s = any;
    r.closest_box_per_ray = box, r.closest_prim_per_ray = prim, r.closest_nodes_per_ray = nodes;
    r.any_box_per_ray = box, r.any_prim_per_ray = prim;
    r.memory_bytes = memory;
    return r;
}

const step_ratio* find(const std::vector<step_ratio>& v, const std::string& scene, const std::string& rays) {
    for (const step_ratio& s : v)
        if (s.scene == scene && s.rays == rays) return &s;
    return nullptr;
}

}  // namespace step_report_test

using namespace step_report_test;

TEST_CASE("11.4 what one step buys: the prediction names two steps of the race, a ratio and a counter", "[ch11][pts:1]") {
    const step_prediction p = my_prediction();
    const auto is_step = [](const std::string& name) {
        for (const step_info& s : all_steps())
            if (name == std::string("ch11-") + s.name) return true;
        return false;
    };
    INFO("before " << p.before << ", after " << p.after << ", ratio " << p.ratio << ", counter " << p.counter);
    CHECK(is_step(p.before));
    CHECK(is_step(p.after));
    CHECK(p.before != p.after);
    CHECK((std::isfinite(p.ratio) && p.ratio > 0.1 && p.ratio < 10.0));
    bool known = p.counter == "none";
    for (const char* c : counter_names) known = known || p.counter == c;
    CHECK(known);
}

TEST_CASE("11.4 what one step buys: ratios paired per process, their median and range, the verdict", "[ch11][pts:2]") {
    // Three processes. bunny diffuse: after / before = 1.10, 1.12, 1.08 in the processes, though the medians
    // of the two rows over the processes (1.62 / 1.5) say 1.08. bunny primary: 1.05 and 0.98 (process 2 has
    // no `after` row there). sponza shadow: only any-hit speeds, 0.9, 0.95, 0.975. Rows of another structure
    // and of rows not asked for are in the way.
    const std::string b = "ch11-variant", a = "ch11-type-sorted";
    std::vector<std::vector<race_csv_row>> processes(3);
    const double diffuse_b[] = {2.0, 1.0, 1.5}, diffuse_a[] = {2.2, 1.12, 1.62};
    const double primary_b[] = {10.0, 12.0, 11.0}, primary_a[] = {10.5, 11.76, 0.0};
    const double shadow_a[] = {3.6, 3.8, 3.9};
    for (int k = 0; k < 3; ++k) {
        auto& rows = processes[std::size_t(k)];
        rows.push_back(row("bunny", "embree-medium", "primary", 20.0, 30.0));
        rows.push_back(row("bunny", b, "primary", primary_b[k], 15.0));
        if (k < 2) rows.push_back(row("bunny", a, "primary", primary_a[k], 14.0));
        rows.push_back(row("bunny", "ch11-soa", "diffuse", 3.0, 4.0));
        rows.push_back(row("bunny", b, "diffuse", diffuse_b[k], 3.0));
        rows.push_back(row("bunny", a, "diffuse", diffuse_a[k], 3.1));
        rows.push_back(row("sponza", a, "shadow", 0.0, shadow_a[k]));
        rows.push_back(row("sponza", b, "shadow", 0.0, 4.0));
    }
    const std::vector<step_ratio> out = compare_steps(processes, b, a);
    REQUIRE(out.size() == 3);
    CHECK((out[0].scene == "bunny" && out[0].rays == "primary"));
    CHECK((out[1].scene == "bunny" && out[1].rays == "diffuse"));
    CHECK((out[2].scene == "sponza" && out[2].rays == "shadow"));

    const step_ratio* d = find(out, "bunny", "diffuse");
    REQUIRE(d != nullptr);
    REQUIRE(d->ratios.size() == 3);
    CHECK(d->ratios[0] == Approx(1.10));
    CHECK(d->ratios[1] == Approx(1.12));
    CHECK(d->ratios[2] == Approx(1.08));
    CHECK(d->median == Approx(1.10));
    CHECK(d->lo == Approx(1.08));
    CHECK(d->hi == Approx(1.12));
    CHECK(d->verdict == "faster");

    const step_ratio* p = find(out, "bunny", "primary");
    REQUIRE(p != nullptr);
    REQUIRE(p->ratios.size() == 2);
    CHECK(p->median == Approx(1.015));
    CHECK(p->lo == Approx(0.98));
    CHECK(p->hi == Approx(1.05));
    CHECK(p->verdict == "level");

    const step_ratio* s = find(out, "sponza", "shadow");
    REQUIRE(s != nullptr);
    REQUIRE(s->ratios.size() == 3);
    CHECK(s->median == Approx(0.95));
    CHECK(s->lo == Approx(0.9));
    CHECK(s->hi == Approx(0.975));
    CHECK(s->verdict == "slower");

    // Turned round, every ratio inverts and the verdicts swap.
    const std::vector<step_ratio> back = compare_steps(processes, a, b);
    const step_ratio* db = find(back, "bunny", "diffuse");
    REQUIRE(db != nullptr);
    CHECK(db->median == Approx(1.0 / 1.10));
    CHECK(db->verdict == "slower");
    // Rows that no process has: nothing to report.
    CHECK(compare_steps(processes, b, "ch11-inlined").empty());
}

TEST_CASE("11.4 what one step buys: the counter that moved most, either way, and none within 1 %", "[ch11][pts:1]") {
    const std::string b = "ch11-type-sorted", a = "ch11-triangles";
    std::vector<std::vector<race_csv_row>> processes(1);
    auto& rows = processes[0];
    // memory 27 MB -> 18 MB, every test counter the same: memory.
    rows.push_back(row("s1", b, "diffuse", 1.0, 1.0, 135.0, 8.2, 40.0, 27e6));
    rows.push_back(row("s1", a, "diffuse", 1.1, 1.0, 135.0, 8.2, 40.0, 18e6));
    // triangle tests +5 %, memory -3 % (800,000 bytes, the largest difference by far): triangle tests.
    rows.push_back(row("s2", b, "diffuse", 1.0, 1.0, 135.0, 8.2, 40.0, 27e6));
    rows.push_back(row("s2", a, "diffuse", 1.0, 1.0, 135.0, 8.61, 40.0, 26.19e6));
    // box tests -3.7 %, triangle tests +3.66 %: the box tests, by the size of the change whatever its sign.
    rows.push_back(row("s3", b, "primary", 1.0, 1.0, 135.0, 8.2, 40.0, 1e6));
    rows.push_back(row("s3", a, "primary", 1.0, 1.0, 130.0, 8.5, 40.0, 1e6));
    // nothing beyond 1 %: none.
    rows.push_back(row("s4", b, "primary", 1.0, 1.0, 100.0, 8.0, 40.0, 1000.0));
    rows.push_back(row("s4", a, "primary", 1.0, 1.0, 100.9, 8.0, 40.2, 995.0));
    // shadow rays: the any-hit counters (here halved), the closest-hit ones left empty by the race.
    race_csv_row sb = row("s5", b, "shadow", 0.0, 2.0, 40.0, 3.0, 0.0, 1e6), sa = row("s5", a, "shadow", 0.0, 2.0, 20.0, 3.0, 0.0, 1e6);
    sb.closest_box_per_ray = sb.closest_prim_per_ray = sa.closest_box_per_ray = sa.closest_prim_per_ray = 0.0;
    rows.push_back(sb), rows.push_back(sa);
    const std::vector<step_ratio> out = compare_steps(processes, b, a);
    REQUIRE(out.size() == 5);
    const step_ratio *s1 = find(out, "s1", "diffuse"), *s2 = find(out, "s2", "diffuse"), *s3 = find(out, "s3", "primary"),
                     *s4 = find(out, "s4", "primary"), *s5 = find(out, "s5", "shadow");
    REQUIRE((s1 && s2 && s3 && s4 && s5));
    CHECK(s1->moved == "memory bytes");
    CHECK(s1->moved_ratio == Approx(18.0 / 27.0));
    CHECK(s2->moved == "triangle tests per ray");
    CHECK(s2->moved_ratio == Approx(8.61 / 8.2));
    CHECK(s3->moved == "box tests per ray");
    CHECK(s3->moved_ratio == Approx(130.0 / 135.0));
    CHECK(s4->moved == "none");
    CHECK(s4->moved_ratio == 1.0);
    CHECK(s5->moved == "box tests per ray");
    CHECK(s5->moved_ratio == Approx(0.5));
}
