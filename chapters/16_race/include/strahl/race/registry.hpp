// Every acceleration structure the race, strahl-trace and the tests know, by name. A chapter adds its
// structure with one line in src/registry.cpp.
#pragma once
#include "strahl/accel.hpp"
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace strahl::race {

struct accel_entry {
    std::string name;         // what --accel takes
    std::string chapter;      // "01", "16", ... (Embree: "--")
    std::string description;  // one line
    std::function<std::unique_ptr<accel>()> make;
    bool linear = false;      // cost grows linearly with triangles (brute force): the race samples its rays
    // The entry whose answers this one must reproduce bit for bit (exact structures): brute force with the
    // same triangle test. "brute" (exercise 01.3's test) for all but chapter 15's watertight rows.
    std::string oracle = "brute";
};

struct registry_options {
    int threads = 1;         // Embree's build threads
    int packet_width = 0;    // image width for Embree's packet and stream rows' tiles (0: no such entries)
};

// In the order the race lists them: brute force first, then the chapters in order, Embree last.
// Embree's entries are present only where Embree was found.
std::vector<accel_entry> registered_accels(const registry_options& options = {});

// The entry of that name; throws std::invalid_argument listing the names otherwise. Beyond the listed
// names, chapter 05's binned SAH with any number of bins K in [2, 256] is found by name, though not raced
// by default: ch05-binnedK (chapter 04's traversal) and ch05-binnedK-fast (the fast builder and traversal),
// e.g. --accels ch05-binned4,ch05-binned64-fast, to see chapter 05's bin-count trade beside Embree. So are
// chapter 15's combinations ch15-TEST-BOX (TEST: mt, mt-epsilon, mt-edges, watertight, watertight-double;
// BOX: plain, conservative, fast) and brute-TEST, each checked against brute-TEST.
accel_entry find_accel(const std::string& name, const registry_options& options = {});

}  // namespace strahl::race
