// Totals over escapes.csv's and spawn.csv's rows (totals.hpp).
#include "strahl/ch15/totals.hpp"
#include "strahl/machine.hpp"
#include "strahl/program.hpp"
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <sstream>
#include <vector>

namespace strahl::ch15 {

namespace {

std::string per_million(double count, double rays) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", rays > 0.0 ? 1e6 * count / rays : 0.0);
    return text;
}

// The first-appearance order of keys, and the counts of each (key, column).
struct grouped {
    std::vector<std::string> keys, columns;
    std::map<std::pair<std::string, std::string>, std::pair<double, double>> sums;  // (rays, escapes)
    void add(const std::string& key, const std::string& column, double rays, double escapes) {
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
        if (std::find(columns.begin(), columns.end(), column) == columns.end()) columns.push_back(column);
        auto& s = sums[{key, column}];
        s.first += rays, s.second += escapes;
    }
    // head: the key columns' names; tail: the machine's values ("" for none). A (key, column) without rows
    // is left empty (brute force ran on the two small spheres only).
    std::string csv(const std::string& head, const std::string& tail) const {
        std::ostringstream out;
        out << head;
        for (const std::string& c : columns) out << ',' << c;
        if (!tail.empty()) out << ',' << machine_header;
        out << '\n';
        for (const std::string& k : keys) {
            out << k;
            for (const std::string& c : columns) {
                const auto s = sums.find({k, c});
                out << ',' << (s == sums.end() ? std::string() : per_million(s->second.second, s->second.first));
            }
            if (!tail.empty()) out << ',' << tail;
            out << '\n';
        }
        return out.str();
    }
};

std::string column_name(const std::string& test, const std::string& box) {
    std::string name = box == "embree" ? test : test + "_" + box;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

}  // namespace

totals_csvs totals(const std::filesystem::path& escapes_file, const std::filesystem::path& spawn_file) {
    totals_csvs out;
    const std::vector<csv_row> escapes =
        read_csv(escapes_file, escapes_csv_header, machine_header, "an escapes.csv written by ch15");
    const std::vector<csv_row> spawn = read_csv(spawn_file, spawn_csv_header, "a spawn.csv written by ch15");
    grouped placement, sphere, aim;
    std::string tail;
    for (const csv_row& r : escapes) {
        const std::vector<std::string>& c = r.cells;
        const std::string column = column_name(c[5], c[6]);
        const double rays = csv_number(escapes_file, r, 8), count = csv_number(escapes_file, r, 9);
        placement.add(c[3] + ',' + c[4], column, rays, count);
        sphere.add(c[0] + ',' + c[1] + ',' + c[2], column, rays, count);
        aim.add(c[7], column, rays, count);
        if (c.size() > 10) tail = csv_field(c[10]) + ',' + c[11] + ',' + csv_field(c[12]) + ',' + csv_field(c[13]);
    }
    // Last, every aim together: the rate over all the rays.
    for (const csv_row& r : escapes)
        aim.add("all", column_name(r.cells[5], r.cells[6]), csv_number(escapes_file, r, 8), csv_number(escapes_file, r, 9));
    out.by_placement = placement.csv("scale,place", tail);
    out.by_sphere = sphere.csv("stacks,slices,triangles", tail);
    out.by_aim = aim.csv("aim", tail);
    // Per offset over every placement.
    std::vector<std::string> offsets;
    std::map<std::string, std::array<double, 3>> s;  // rays, self-hits, leaks
    for (const csv_row& r : spawn) {
        const std::string& k = r.cells[2];
        if (std::find(offsets.begin(), offsets.end(), k) == offsets.end()) offsets.push_back(k);
        auto& v = s[k];
        v[0] += csv_number(spawn_file, r, 3), v[1] += csv_number(spawn_file, r, 6), v[2] += csv_number(spawn_file, r, 7);
    }
    std::ostringstream csv;
    csv << "offset,rays,self_hits,leaks,self_hits_per_million,leaks_per_million\n";
    for (const std::string& k : offsets) {
        const auto& v = s[k];
        csv << k << ',' << std::uint64_t(v[0]) << ',' << std::uint64_t(v[1]) << ',' << std::uint64_t(v[2]) << ','
            << per_million(v[1], v[0]) << ',' << per_million(v[2], v[0]) << '\n';
    }
    out.spawn = csv.str();
    return out;
}

}  // namespace strahl::ch15
