// The totals the chapter's texts quote (totals.hpp): sums of counts over escapes.csv's and spawn.csv's rows,
// then one division, per placement, sphere, aim and offset; a file that is neither refused.
#include "strahl/ch15/totals.hpp"
#include "strahl/program.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch15;

TEST_CASE("ch15 totals: rates over all rows of a group, a column per test and box", "[ch15][totals]") {
    const auto dir = test::scratch_dir("ch15_totals");
    write_text(dir / "escapes.csv",
               "stacks,slices,triangles,scale,place,test,box,aim,rays,escapes,cpu,threads,kernels,date\n"
               "12,24,528,1,0,mt,fast,vertex,100,10,AMD EPYC,2,AVX512,2026-12-05\n"
               "12,24,528,1,0,mt,fast,edge,300,0,AMD EPYC,2,AVX512,2026-12-05\n"
               "12,24,528,1,0,embree-robust,embree,vertex,100,1,AMD EPYC,2,AVX512,2026-12-05\n"
               "48,96,9216,1,0,mt,fast,vertex,1000,3,AMD EPYC,2,AVX512,2026-12-05\n"
               "12,24,528,1000,1e+06,mt,fast,vertex,100,50,AMD EPYC,2,AVX512,2026-12-05\n");
    write_text(dir / "spawn.csv",
               "scale,place,offset,rays,outward_self_hits,inward_self_hits,self_hits,leaks,self_hits_per_million,"
               "leaks_per_million\n"
               "1,0,none,400,100,99,199,0,497500,0\n"
               "1,0,fixed,400,0,0,0,2,0,5000\n"
               "1000,0,none,600,1,0,1,0,1666.67,0\n");
    const totals_csvs t = totals(dir / "escapes.csv", dir / "spawn.csv");
    // Placement (1, 0): mt_fast 13 of 1,400 rays (not the mean of the rows' rates); embree_robust 1 of 100.
    CHECK(t.by_placement ==
          "scale,place,mt_fast,embree_robust,cpu,threads,kernels,date\n"
          "1,0,9285.7,10000.0,AMD EPYC,2,AVX512,2026-12-05\n"
          "1000,1e+06,500000.0,,AMD EPYC,2,AVX512,2026-12-05\n");
    CHECK(t.by_sphere ==
          "stacks,slices,triangles,mt_fast,embree_robust,cpu,threads,kernels,date\n"
          "12,24,528,120000.0,10000.0,AMD EPYC,2,AVX512,2026-12-05\n"
          "48,96,9216,3000.0,,AMD EPYC,2,AVX512,2026-12-05\n");
    CHECK(t.by_aim ==
          "aim,mt_fast,embree_robust,cpu,threads,kernels,date\n"
          "vertex,52500.0,10000.0,AMD EPYC,2,AVX512,2026-12-05\n"
          "edge,0.0,,AMD EPYC,2,AVX512,2026-12-05\n"
          "all,42000.0,10000.0,AMD EPYC,2,AVX512,2026-12-05\n");  // mt_fast: 63 of 1,500 rays
    CHECK(t.spawn ==
          "offset,rays,self_hits,leaks,self_hits_per_million,leaks_per_million\n"
          "none,1000,200,0,200000.0,0.0\n"
          "fixed,400,0,2,0.0,5000.0\n");
    // A spawn.csv where an escapes.csv belongs: refused, naming the file.
    CHECK_THROWS_WITH(totals(dir / "spawn.csv", dir / "spawn.csv"), Catch::Contains("spawn.csv") &&
                                                                       Catch::Contains("escapes.csv written by ch15"));
}
