// The race over several processes (processes.hpp): race.csv reads back as it was written, and the combined
// rows take each figure's median across processes, the ratios to Embree as medians of each process's own
// ratio, the worst differing count, and the sum of timed runs; spread.svg draws a line per structure.
#include "strahl/race/processes.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <fstream>

using namespace strahl;
using namespace strahl::race;
using strahl::test::scratch_dir;

namespace {

race_row row(const std::string& accel, const std::string& rays, double build_ms, double closest, double any) {
    race_row r;
    r.scene = "teapot";
    r.triangles = 4096;
    r.accel = accel;
    r.chapter = accel == "embree-medium" ? "embree" : "05";
    r.exact = accel != "embree-medium";
    r.ray_set = rays;
    r.build_ms = build_ms;
    r.memory_bytes = 1000;
    if (r.exact) r.sah = 22.5;
    r.closest = {closest, 5, 100, 0, 30.5, 2.25, 15.0};
    r.any = {any, 4, 100, 0, 20.0, 1.5, std::nullopt};
    return r;
}

const machine_columns here{"AMD EPYC", "AVX512", "2026-12-05", 1};

}  // namespace

TEST_CASE("ch16 processes: race.csv reads back as to_csv wrote it", "[ch16][processes]") {
    std::vector<race_row> rows = {row("ch05-binned16-fast", "primary", 1.25, 20.5, 22.0),
                                  row("embree-medium", "primary", 1.5, 16.0, 18.0)};
    rows[0].closest.differing = 3;
    rows.push_back(row("ch05-binned16-fast", "shadow", 1.0, 0.0, 6.0));
    rows.back().closest = {};  // shadow rays: no closest-hit query
    add_embree_ratios(rows);
    const auto dir = scratch_dir("ch16_processes_csv");
    std::ofstream(dir / "race.csv") << to_csv(rows, here);
    const std::vector<race_row> back = read_race_csv(dir / "race.csv");
    REQUIRE(back.size() == rows.size());
    CHECK(to_csv(back, here) == to_csv(rows, here));
    CHECK(back[0].closest.differing == 3);
    CHECK(back[0].exact);
    CHECK_FALSE(back[1].exact);
    CHECK_FALSE(back[1].sah);
    REQUIRE(back[0].closest_vs_embree);
    CHECK(*back[0].closest_vs_embree == Approx(20.5 / 16.0).epsilon(1e-5));
    CHECK(back[2].closest.runs == 0);
    CHECK(back[2].any.mrays == 6.0);

    // A scene named with a comma and a quote (a file stem may hold both) reads back whole.
    rows[0].scene = rows[1].scene = "sponza, \"inside\"";
    std::ofstream(dir / "named.csv") << to_csv(rows, here);
    const std::vector<race_row> named = read_race_csv(dir / "named.csv");
    REQUIRE(named.size() == rows.size());
    CHECK(named[0].scene == rows[0].scene);
    CHECK(named[0].triangles == rows[0].triangles);
    CHECK(to_csv(named, here) == to_csv(rows, here));

    // The machine's columns: each row names the CPU, the threads, Embree's kernels and the date; a row read
    // back keeps its CPU. A file written before those columns still reads (its rows name no CPU).
    const std::string written = to_csv(rows, here);
    CHECK(written.substr(0, written.find('\n')) == std::string(race_csv_header) + "," + race_csv_machine_header);
    CHECK(written.find(",AMD EPYC,1,AVX512,2026-12-05\n") != std::string::npos);
    CHECK(back[0].cpu == "AMD EPYC");
    CHECK(to_csv(back, machine_columns{"Intel Xeon", "AVX2", "2027-01-01", 2}).find(",AMD EPYC,2,AVX2,2027-01-01\n") !=
          std::string::npos);
    std::string old;
    for (std::size_t at = 0; at < written.size();) {  // every line without its last four fields
        std::string line = written.substr(at, written.find('\n', at) - at);
        at += line.size() + 1;
        for (int k = 0; k < 4; ++k) line.erase(line.rfind(','));
        old += line + "\n";
    }
    std::ofstream(dir / "old.csv") << old;
    const std::vector<race_row> before = read_race_csv(dir / "old.csv");
    REQUIRE(before.size() == rows.size());
    CHECK(before[0].cpu.empty());
    CHECK(before[0].build_ms == back[0].build_ms);
    CHECK(read_race_rows(dir / "old.csv").size() == rows.size());  // the chapters' reader alike
    CHECK(read_race_rows(dir / "race.csv")[0].cpu == "AMD EPYC");

    // Anything else is refused, naming the file.
    std::ofstream(dir / "other.csv") << "scene,structure\nteapot,x\n";
    CHECK_THROWS_WITH(read_race_csv(dir / "other.csv"), Catch::Contains("other.csv"));
    std::string text = to_csv(rows, here);
    text.replace(text.find("1.250"), 5, "fast!");
    std::ofstream(dir / "bad.csv") << text;
    CHECK_THROWS_WITH(read_race_csv(dir / "bad.csv"), Catch::Contains("line 2"));
}

TEST_CASE("ch16 processes: figures combine as medians across processes", "[ch16][processes]") {
    // Three processes; the second is slow for both structures (a whole-process outlier), the third measured
    // one more row.
    std::vector<std::vector<race_row>> p(3);
    p[0] = {row("ch05-binned16-fast", "primary", 60.0, 1.5, 2.0), row("embree-medium", "primary", 80.0, 2.5, 3.0)};
    p[1] = {row("embree-medium", "primary", 100.0, 2.0, 2.5), row("ch05-binned16-fast", "primary", 85.0, 1.0, 1.25)};
    p[2] = {row("ch05-binned16-fast", "primary", 62.0, 1.6, 2.1), row("embree-medium", "primary", 78.0, 2.6, 3.2),
            row("ch04-median", "primary", 50.0, 1.0, 1.0)};
    p[2][0].closest.differing = 2;
    for (auto& rows : p) add_embree_ratios(rows);
    const std::vector<combined_row> c = combine_processes(p);
    REQUIRE(c.size() == 3);
    // The first process's order; the row only the third process has comes last, with one sample.
    CHECK(c[0].row.accel == "ch05-binned16-fast");
    CHECK(c[1].row.accel == "embree-medium");
    CHECK(c[2].row.accel == "ch04-median");
    CHECK(c[2].build_ms.samples == 1);
    CHECK(c[2].row.build_ms == 50.0);

    const combined_row& fast = c[0];
    CHECK(fast.build_ms.samples == 3);
    CHECK(fast.row.build_ms == 62.0);
    CHECK(fast.build_ms.min == 60.0);
    CHECK(fast.build_ms.max == 85.0);
    CHECK(fast.row.closest.mrays == 1.5);
    CHECK(fast.row.any.mrays == 2.0);
    // Ratios: each process's own (0.6, 0.5, 0.615...), their median 0.6; not 1.5 / 2.5 of the medians' ratio
    // by accident: the any-hit ratios (0.667, 0.5, 0.656) have median 0.656, while 2.0 / 3.0 = 0.667.
    REQUIRE(fast.row.closest_vs_embree);
    CHECK(*fast.row.closest_vs_embree == Approx(0.6));
    REQUIRE(fast.row.any_vs_embree);
    CHECK(*fast.row.any_vs_embree == Approx(2.1 / 3.2));
    CHECK(fast.closest_vs_embree.min == Approx(0.5));
    // The worst differing count, the sum of the timed runs.
    CHECK(fast.row.closest.differing == 2);
    CHECK(fast.row.closest.runs == 15);
    CHECK(fast.row.any.runs == 12);
    CHECK(c[2].row.closest_vs_embree);  // the third process raced Embree too
    // Without Embree in the race: no ratio.
    const std::vector<combined_row> alone = combine_processes({{row("ch04-median", "diffuse", 1.0, 1.0, 1.0)}});
    REQUIRE(alone.size() == 1);
    CHECK_FALSE(alone[0].row.closest_vs_embree);
    CHECK(alone[0].closest_vs_embree.samples == 0);

    // One table, one machine: processes that ran on two CPUs do not combine.
    std::vector<std::vector<race_row>> two_cpus = {p[0], p[0]};
    for (race_row& r : two_cpus[0]) r.cpu = "AMD EPYC";
    for (race_row& r : two_cpus[1]) r.cpu = "Intel Xeon";
    CHECK_THROWS_WITH(combine_processes(two_cpus), Catch::Contains("different CPUs"));
    for (race_row& r : two_cpus[1]) r.cpu = "AMD EPYC";
    CHECK(combine_processes(two_cpus).size() == 2);

    // Another race's process (other rays, or another scene under the same name) does not combine.
    std::vector<std::vector<race_row>> other = {p[0], p[0]};
    other[1][0].closest.rays = other[1][0].any.rays = 200;
    CHECK_THROWS_WITH(combine_processes(other), Catch::Contains("did not run the same race"));
    other[1][0].closest.rays = other[1][0].any.rays = 100;
    other[1][0].triangles = 4095;
    CHECK_THROWS_WITH(combine_processes(other), Catch::Contains("did not run the same race"));

    // spread.svg: one panel (one scene and ray set), a line per structure, a point per process that ran it.
    const std::vector<plot> panels = spread_plot(p);
    REQUIRE(panels.size() == 1);
    CHECK(panels[0].log_y);
    REQUIRE(panels[0].series.size() == 3);
    CHECK(panels[0].series[0].label == "ch05-binned16-fast");
    CHECK(panels[0].series[0].x == std::vector<double>{1, 2, 3});
    CHECK(panels[0].series[0].y == std::vector<double>{1.5, 1.0, 1.6});
    CHECK(panels[0].series[2].x == std::vector<double>{3});

    const std::string md = spread_markdown(c, 3, "test machine");
    CHECK_THAT(md, Catch::Contains("62.00 (60.00 to 85.00)"));
    CHECK_THAT(md, Catch::Contains("| 50.00 |"));  // one sample: no brackets
}

TEST_CASE("ch16 processes: the claim rule compares two rows within each process", "[ch16][processes]") {
    // The verdict: faster only where A beat B in every process, slower only where B beat A in every one.
    CHECK(verdict_of({1.01, 1.2, 1.05, 1.3, 1.02}) == "faster");
    CHECK(verdict_of({0.99, 0.8, 0.95, 0.7, 0.98}) == "slower");
    CHECK(verdict_of({1.2, 1.3, 0.99, 1.25, 1.4}) == "level");  // one process against: the noise covers the gap
    CHECK(verdict_of({1.0, 1.3, 1.1, 1.25, 1.4}) == "level");   // a tie is not a win
    CHECK(verdict_of({1.2, 1.3, 1.1, 1.25}) == "too few processes");

    // Five processes; the third is slow as a whole, the fifth faster: the paired ratios ignore both. A is
    // ahead of B on closest hit in every process; on any hit the fourth process has B ahead.
    std::vector<std::vector<race_row>> p;
    const double scale[5] = {1.0, 1.0, 0.6, 1.0, 1.4};
    const double any_a[5] = {2.2, 2.1, 2.3, 1.9, 2.2};
    for (int k = 0; k < 5; ++k) {
        p.push_back({row("A", "primary", 1.0, 1.1 * scale[k], any_a[k] * scale[k]),
                     row("B", "primary", 1.0, 1.0 * scale[k], 2.0 * scale[k])});
        if (k % 2) std::swap(p.back()[0], p.back()[1]);  // the reversed order of every second process
    }
    const std::vector<comparison> c = compare_rows(p, "A", "B");
    REQUIRE(c.size() == 2);
    CHECK(c[0].query == "closest");
    CHECK(c[0].ratios.size() == 5);
    CHECK(c[0].ratio.median == Approx(1.1));
    CHECK(c[0].ratio.min == Approx(1.1));
    CHECK(c[0].verdict == "faster");
    CHECK(c[1].query == "any");
    CHECK(c[1].ratio.median == Approx(1.1));
    CHECK(c[1].ratio.min == Approx(0.95));
    CHECK(c[1].verdict == "level");
    const std::vector<comparison> back = compare_rows(p, "B", "A");
    CHECK(back[0].verdict == "slower");
    CHECK(back[0].ratio.median == Approx(1.0 / 1.1));

    // The CSV: a line per comparison, each process's ratio at its end.
    const std::string csv = comparisons_csv(c);
    CHECK(csv.rfind("scene,rays,query,a,b,processes,ratio_median,ratio_min,ratio_max,verdict,ratios\n", 0) == 0);
    CHECK(csv.find("teapot,primary,closest,A,B,5,1.1,1.1,1.1,faster,1.1 1.1 1.1 1.1 1.1\n") != std::string::npos);
    CHECK(comparisons_markdown(c, "test machine").find("| teapot | primary | any | A | B | 5 |") != std::string::npos);

    // A row no process measured is named.
    CHECK_THROWS_WITH(compare_rows(p, "A", "C"), Catch::Contains("'C'"));
}

TEST_CASE("ch16 processes: verdicts held against an earlier run's compare.csv", "[ch16][processes]") {
    // Two runs of the same pairs: A over B faster in both; on any hit faster, then level; C over B level in
    // both; one pair the later run lacks, one the earlier lacked.
    const auto pairs = [](double any4, double c) {
        std::vector<std::vector<race_row>> p;
        for (int k = 0; k < 5; ++k)
            p.push_back({row("A", "primary", 1.0, 1.2, k == 3 ? any4 : 2.4), row("B", "primary", 1.0, 1.0, 2.0),
                         row("C", "primary", 1.0, k == 1 ? c : 1.1, 2.1)});
        return p;
    };
    std::vector<comparison> earlier = compare_rows(pairs(2.4, 0.9), "A", "B");
    const std::vector<comparison> c1 = compare_rows(pairs(2.4, 0.9), "C", "B");
    earlier.insert(earlier.end(), c1.begin(), c1.end());
    std::vector<comparison> now = compare_rows(pairs(1.9, 0.9), "A", "B");
    const std::vector<comparison> c2 = compare_rows(pairs(1.9, 0.9), "C", "A");
    now.insert(now.end(), c2.begin(), c2.end());

    // Through the CSV and back: the same figures and verdicts.
    const auto dir = scratch_dir("ch16_processes_verdicts");
    std::ofstream(dir / "compare.csv") << comparisons_csv(earlier);
    const std::vector<comparison> back = read_comparisons_csv(dir / "compare.csv");
    REQUIRE(back.size() == earlier.size());
    CHECK(comparisons_csv(back) == comparisons_csv(earlier));
    CHECK(back[1].ratios.size() == 5);

    const verdict_stability s = compare_verdicts(back, now);
    CHECK(s.both == 2);  // A:B closest and any; C:B and C:A are not the same pair
    CHECK(s.held == 1);
    REQUIRE(s.changed.size() == 1);
    CHECK(s.changed[0].now.query == "any");
    CHECK(s.changed[0].earlier.verdict == "faster");
    CHECK(s.changed[0].now.verdict == "level");
    CHECK(s.opposite == 0);
    const std::string md = stability_markdown(s, "run 1");
    CHECK(md.find("2 in both, 1 with the same verdict, 1 changed (0 from faster to slower or back)") != std::string::npos);
    CHECK(md.find("| teapot | primary | any | A | B | 1.200 (1.200 to 1.200) | faster | 1.200 (0.950 to 1.200) | level |") !=
          std::string::npos);

    // Faster in one run, slower in the other: opposite.
    std::vector<comparison> flipped = earlier;
    for (comparison& c : flipped) c.verdict = c.verdict == "faster" ? "slower" : c.verdict;
    CHECK(compare_verdicts(earlier, flipped).opposite == 3);  // A:B closest and any, C:B any

    // Not a compare.csv: named, with its line.
    std::ofstream(dir / "race.csv") << "scene,rays\nteapot,primary\n";
    CHECK_THROWS_WITH(read_comparisons_csv(dir / "race.csv"), Catch::Contains("race.csv"));
    std::ofstream(dir / "bad.csv") << "scene,rays,query,a,b,processes,ratio_median,ratio_min,ratio_max,verdict,ratios\n"
                                   << "teapot,primary,nearest,A,B,5,1,1,1,level,1 1 1 1 1\n";
    CHECK_THROWS_WITH(read_comparisons_csv(dir / "bad.csv"), Catch::Contains("line 2") && Catch::Contains("nearest"));
    std::ofstream(dir / "bad_ratio.csv") << compare_csv_header << "\n"
                                         << "teapot,primary,any,A,B,5,1,1,1,level,1 1 x1 1 1\n";
    CHECK_THROWS_WITH(read_comparisons_csv(dir / "bad_ratio.csv"), Catch::Contains("'x1'"));
}
