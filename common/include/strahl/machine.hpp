// The machine a measurement ran on. One table, one machine: every CSV of timings a program writes ends each
// row with four columns, cpu,threads,kernels,date (the race's race.csv since it had them; the chapters'
// measured tables through stamp_machine), and tests/check_numbers.sh reads the cpu column to check that the
// text beside a table names the processor its numbers came from. CSVs that hold no timing (counts, images'
// statistics, tables redrawn from committed files) carry no machine: they read the same on any.
#pragma once
#include <filesystem>
#include <string>

namespace strahl {

// cpu: the model /proc/cpuinfo names ("AMD EPYC 9R14 96-Core Processor"); threads: the most threads the table's
// timings could use; kernels: the instruction set of Embree's kernels on this machine ("AVX512"; "none" where
// the course was built without Embree); date: the day, YYYY-MM-DD (UTC).
struct machine_columns {
    std::string cpu, kernels, date;
    int threads = 1;
};
inline constexpr const char* machine_header = "cpu,threads,kernels,date";

// This machine's, for timings on `threads` threads.
machine_columns this_machine(int threads);

// A CSV's text with the machine's columns added: machine_header to its first line, the values to every
// other non-empty line (fields quoted as csv_field quotes them).
std::string with_machine(const std::string& csv, const machine_columns& m);

// with_machine on a CSV file a program has just written, in place.
void stamp_machine(const std::filesystem::path& csv, int threads);

}  // namespace strahl
