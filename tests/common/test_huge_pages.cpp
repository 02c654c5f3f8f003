// huge_pages.hpp: large arrays on 2 MiB boundaries, advised for transparent huge pages; small ones as before.
#include "strahl/huge_pages.hpp"
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

constexpr std::size_t huge = std::size_t(2) << 20;

// Calls f(line) for each line of /proc/self/smaps that describes a mapping overlapping [p, p + bytes).
template <class F>
void for_mappings(const void* p, std::size_t bytes, F&& f) {
    std::ifstream smaps("/proc/self/smaps");
    const auto a = reinterpret_cast<std::uintptr_t>(p), b = a + bytes;
    std::string line;
    bool overlaps = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> lo >> dash >> hi && dash == '-') overlaps = lo < b && a < hi;
        else if (overlaps) f(line);
    }
}

// The VmFlags line of the mapping that holds address p ("" where none is found).
std::string vm_flags_at(const void* p) {
    std::string flags;
    for_mappings(p, 1, [&](const std::string& line) {
        if (line.rfind("VmFlags:", 0) == 0) flags = line;
    });
    return flags;
}

// The resident bytes (smaps' Rss) of the mappings that overlap [p, p + bytes).
std::size_t resident_bytes(const void* p, std::size_t bytes) {
    std::size_t kib = 0;
    for_mappings(p, bytes, [&](const std::string& line) {
        if (line.rfind("Rss:", 0) != 0) return;
        std::size_t k = 0;
        std::istringstream(line.substr(4)) >> k;
        kib += k;
    });
    return kib * 1024;
}

}  // namespace

TEST_CASE("huge_vector: a large array starts on a 2 MiB boundary and holds what is written", "[huge_pages]") {
    strahl::huge_vector<float> v(3 * huge / sizeof(float) + 5);
    CHECK(reinterpret_cast<std::uintptr_t>(v.data()) % huge == 0);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = float(i % 1000);
    bool same = true;
    for (std::size_t i = 0; i < v.size(); ++i) same = same && v[i] == float(i % 1000);
    CHECK(same);
    v.push_back(1.0f);  // a reallocation goes through the allocator again
    CHECK(reinterpret_cast<std::uintptr_t>(v.data()) % huge == 0);
    CHECK(v.back() == 1.0f);
}

TEST_CASE("huge_vector: an array of 64 KiB to 2 MiB starts on a page", "[huge_pages]") {
    strahl::huge_vector<double> v(100000, 0.5);
    CHECK(reinterpret_cast<std::uintptr_t>(v.data()) % 4096 == 0);
    CHECK(v[99999] == 0.5);
}

TEST_CASE("huge_vector: small arrays come from the ordinary allocator", "[huge_pages]") {
    strahl::huge_vector<std::uint32_t> v(100, 7u);
    CHECK(v.size() == 100);
    CHECK(v[99] == 7u);
    strahl::huge_vector<std::uint32_t> w = v;
    CHECK(w == v);
    v.clear();
    v.shrink_to_fit();
    CHECK(w[0] == 7u);
}

TEST_CASE("huge_vector: Linux is asked for huge pages (the mapping carries the hg flag)", "[huge_pages]") {
    if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled")) {
        WARN("no transparent huge pages on this system: the advice is not given, nothing to check");
        return;
    }
    strahl::huge_vector<char> v(4 * huge, 1);
    const std::string flags = vm_flags_at(v.data() + huge);
    // The memory held is the array's: a tail past the last whole 2 MiB stays on 4 KiB pages (rounded up to
    // 2 MiB and populated, it held 6 MiB for this 4.1 MiB array).
    strahl::huge_vector<char> tail(2 * huge + 100 * 1024, 1);
    const std::size_t held = resident_bytes(tail.data(), tail.size());
    INFO("resident: " << held << " bytes for an array of " << tail.size());
    CHECK(held <= tail.size() + 3 * 4096);
    CHECK(held >= tail.size());
    INFO("VmFlags of the array's mapping: " << flags);
    CHECK(flags.find(" hg") != std::string::npos);
    // Without the advice (the race's --plain-pages), the mapping does not ask.
    strahl::page_advice = false;
    strahl::huge_vector<char> plain(4 * huge, 1);
    strahl::page_advice = true;
    const std::string plain_flags = vm_flags_at(plain.data() + huge);
    INFO("VmFlags without the advice: " << plain_flags);
    CHECK(plain_flags.find(" hg") == std::string::npos);
}
