// The spawn test's and the escape test's totals over their rows, as the chapter's texts quote them: each
// offset over all placements (spawn.csv), and each triangle test behind each box test per placement, per
// sphere and per aim (escapes.csv), in rays per million. Sums of counts, then one division: a rate over
// all the rows, not a mean of the rows' rates.
#pragma once
#include <filesystem>
#include <string>

namespace strahl::ch15 {

// The headers of the two files the program writes and the totals read back (escapes.csv also ends with the
// machine's columns, strahl/machine.hpp).
inline constexpr const char* escapes_csv_header = "stacks,slices,triangles,scale,place,test,box,aim,rays,escapes";
inline constexpr const char* spawn_csv_header =
    "scale,place,offset,rays,outward_self_hits,inward_self_hits,self_hits,leaks,self_hits_per_million,leaks_per_million";

struct totals_csvs {
    std::string spawn;         // spawn_totals.csv: offset,rays,self_hits,leaks,self_hits_per_million,leaks_per_million
    std::string by_placement;  // escapes_by_placement.csv: scale,place, then one column per test and box
    std::string by_sphere;     // escapes_by_sphere.csv: stacks,slices,triangles, then the same columns
    std::string by_aim;        // escapes_by_aim.csv: aim, then the same columns; a last row "all": every ray
};

// From the escapes.csv and spawn.csv this program wrote (read back with read_csv: a file that is neither
// is refused naming it). The escape tables carry escapes.csv's machine columns (Embree's counts depend on
// its kernels); spawn_totals.csv, like spawn.csv, none. A column per (test, box) in the order of their first
// row: "mt_fast", "watertight_double_plain", ..., and Embree's as "embree" and "embree_robust".
totals_csvs totals(const std::filesystem::path& escapes_csv, const std::filesystem::path& spawn_csv);

}  // namespace strahl::ch15
