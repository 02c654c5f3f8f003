#include "strahl/race/reference_cache.hpp"
#include "strahl/race/measure.hpp"
#include "strahl/race/ray_io.hpp"
#include "strahl/race/ray_sets.hpp"
#include "strahl/scene.hpp"
#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdio>
#include <functional>
#include <iostream>
#include <regex>

namespace strahl::race {

namespace {

// FNV-1a, 64 bits, over the bit patterns of floats (so -0 and +0, or two NaNs, hash apart).
struct fnv1a {
    std::uint64_t h = 14695981039346656037ull;
    void add(std::uint32_t word) {
        for (int k = 0; k < 4; ++k) h = (h ^ ((word >> (8 * k)) & 0xFFu)) * 1099511628211ull;
    }
    void add(float f) { add(std::bit_cast<std::uint32_t>(f)); }
    void add(const vec3& v) { add(v.x), add(v.y), add(v.z); }
    void add(const std::string& s) {
        for (const char c : s) h = (h ^ std::uint8_t(c)) * 1099511628211ull;
    }
};

// The race's own rule for exact structures (measure.hpp): both misses, or the same primitive with
// bit-identical t, u and v.
bool same(const hit& a, const hit& b) { return agrees(a, b, true); }

// The audit's rays: up to reference_cache::audit_rays evenly spread over the set, and as many again evenly
// spread over the rays the file says hit something (in a set where most rays miss, the first alone would
// check few hits).
bool says_hit(const hit& h) { return h.found(); }
bool says_hit(std::uint8_t blocked) { return blocked != 0; }

template <class Answer>
std::vector<std::size_t> audit_sample(const std::vector<Answer>& cached) {
    const auto spread = [](const std::vector<std::size_t>& from, std::vector<std::size_t>& to) {
        const std::size_t m = std::min(from.size(), reference_cache::audit_rays);
        for (std::size_t k = 0; k < m; ++k) to.push_back(from[k * from.size() / m]);
    };
    std::vector<std::size_t> all(cached.size()), hits, ids;
    for (std::size_t i = 0; i < cached.size(); ++i) {
        all[i] = i;
        if (says_hit(cached[i])) hits.push_back(i);
    }
    spread(all, ids);
    spread(hits, ids);
    return ids;
}

enum class cached { absent, usable, rejected };

// Loads a cached answer file and checks it: the right count, and the sample traced again agrees. Says why
// on stdout when a file is there but cannot be used.
template <class Answer, class Read, class Trace, class Same>
cached load(const std::filesystem::path& f, std::span<const ray> rays, std::vector<Answer>& out, Read read,
            Trace trace, Same agree) {
    std::error_code ec;
    if (!std::filesystem::exists(f, ec)) return cached::absent;
    try {
        out = read(f);
    } catch (const format_error& e) {
        std::cout << "  reference cache: " << e.what() << "; tracing again\n";
        return cached::rejected;
    }
    if (out.size() != rays.size()) {
        std::cout << "  reference cache: '" << f.string() << "' holds " << out.size() << " answers, not "
                  << rays.size() << "; tracing again\n";
        return cached::rejected;
    }
    const std::vector<std::size_t> ids = audit_sample(out);
    std::vector<ray> sample;
    for (const std::size_t i : ids) sample.push_back(rays[i]);
    std::vector<Answer> fresh(sample.size());
    trace(sample, fresh);
    std::size_t differ = 0;
    for (std::size_t k = 0; k < ids.size(); ++k) differ += !agree(fresh[k], out[ids[k]]);
    if (differ == 0) return cached::usable;
    std::cout << "  reference cache: '" << f.string() << "' is stale (" << differ << " of " << ids.size()
              << " sampled rays differ from brute force now); tracing again\n";
    return cached::rejected;
}

}  // namespace

reference_cache::reference_cache(std::filesystem::path folder, const scene& s, const brute_force& exact, int threads)
    : folder_(std::move(folder)), exact_(exact), threads_(threads) {
    // The file names start with the scene's name, made safe for a file name.
    stem_ = std::filesystem::path(s.name).stem().string();
    for (char& c : stem_)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    if (stem_.empty()) stem_ = "scene";
    fnv1a h;
    h.add(std::string("strahl brute-force reference, format 1"));
    h.add(std::uint32_t(s.mesh.triangle_count()));
    for (std::size_t i = 0; i < s.mesh.triangle_count(); ++i)
        for (const vec3& v : s.mesh.triangle(i)) h.add(v);
    scene_hash_ = h.h;
}

std::filesystem::path reference_cache::file(const std::string& set, const char* query, std::span<const ray> rays) const {
    fnv1a h;
    h.h = scene_hash_;
    h.add(std::string(query));
    h.add(std::uint32_t(rays.size()));
    for (const ray& r : rays) h.add(r.org), h.add(r.tmin), h.add(r.dir), h.add(r.tmax);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h.h));
    return folder_ / (stem_ + "_" + set + "_" + query + "_" + hex + (query[0] == 'c' ? ".hits" : ".flags"));
}

// The answers from the file when it is usable; else traced, and written through a temporary file and a
// rename, so that an interrupted run leaves no half-written file. A cache that cannot be written is no
// error: the race says so once and goes on without it.
template <class Answer, class Read, class Write, class Trace, class Same>
std::vector<Answer> reference_cache::answers(const std::string& set, const char* query, std::span<const ray> rays,
                                             Read read, Write write, Trace trace, Same agree) {
    std::vector<Answer> out;
    const std::filesystem::path f = folder_.empty() ? std::filesystem::path() : file(set, query, rays);
    if (!f.empty()) {
        const cached c = load(f, rays, out, read, trace, agree);
        if (c == cached::usable) {
            // Touched: the file was used now (prune_reference_cache removes the least recently used).
            std::error_code ec;
            std::filesystem::last_write_time(f, std::filesystem::file_time_type::clock::now(), ec);
            ++loaded_;
            return out;
        }
        stale_ += c == cached::rejected;
    }
    out.assign(rays.size(), Answer{});
    trace(rays, out);
    ++traced_;
    if (f.empty()) return out;
    std::error_code ec;
    std::filesystem::create_directories(folder_, ec);
    std::filesystem::path tmp = f;
    tmp += ".tmp";
    try {
        if (ec) throw format_error("cannot create folder '" + folder_.string() + "': " + ec.message());
        write(tmp, std::span<const Answer>(out));
        std::filesystem::rename(tmp, f);
    } catch (const std::exception& e) {
        std::filesystem::remove(tmp, ec);
        std::cout << "  reference cache: " << e.what() << "; going on without the cache\n";
        folder_.clear();
    }
    return out;
}

std::vector<hit> reference_cache::closest(const std::string& set, std::span<const ray> rays) {
    return answers<hit>(
        set, "closest", rays, read_hits, write_hits,
        [this](std::span<const ray> r, std::vector<hit>& out) { trace_closest(exact_, r, out, threads_); }, same);
}

std::vector<std::uint8_t> reference_cache::any(const std::string& set, std::span<const ray> rays) {
    return answers<std::uint8_t>(
        set, "any", rays, read_flags, write_flags,
        [this](std::span<const ray> r, std::vector<std::uint8_t>& out) { trace_any(exact_, r, out, threads_); },
        std::equal_to<std::uint8_t>());
}

pruned_files prune_reference_cache(const std::filesystem::path& folder, std::uintmax_t max_bytes,
                                   std::filesystem::file_time_type since) {
    // The cache's own files: NAME_SET_QUERY_HASH.hits or .flags (file() above), perhaps with .tmp after it.
    static const std::regex ours(R"(.+_(closest|any)_[0-9a-f]{16}\.(hits|flags)(\.tmp)?)");
    struct entry {
        std::filesystem::path path;
        std::uintmax_t bytes;
        std::filesystem::file_time_type time;
    };
    std::vector<entry> files;
    std::uintmax_t total = 0;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
        if (!e.is_regular_file(ec) || !std::regex_match(e.path().filename().string(), ours)) continue;
        const std::uintmax_t bytes = e.file_size(ec);
        if (ec) continue;
        files.push_back({e.path(), bytes, e.last_write_time(ec)});
        total += bytes;
    }
    std::sort(files.begin(), files.end(), [](const entry& a, const entry& b) { return a.time < b.time; });
    pruned_files removed;
    for (const entry& f : files) {
        if (total <= max_bytes || f.time >= since) break;
        if (!std::filesystem::remove(f.path, ec)) continue;
        total -= f.bytes;
        removed.bytes += f.bytes;
        ++removed.files;
    }
    return removed;
}

}  // namespace strahl::race
