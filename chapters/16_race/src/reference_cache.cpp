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
#include <optional>
#include <regex>
#include <utility>

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

// The checksum of an answer set: FNV-1a over the hash of the inputs it was traced for (the scene's triangles
// and the rays, as in the file's name) and then every answer, as the file stores it. A file whose answers no
// longer give the checksum in its name was corrupted or altered after it was written, in any record: the
// audit below re-traces only a sample and would miss most such changes.
std::uint64_t checksum(std::uint64_t inputs, std::span<const hit> answers) {
    fnv1a h;
    h.h = inputs;
    h.add(std::string("closest"));
    h.add(std::uint32_t(answers.size())), h.add(std::uint32_t(std::uint64_t(answers.size()) >> 32));
    for (const hit& a : answers) h.add(a.t), h.add(a.prim), h.add(a.u), h.add(a.v);
    return h.h;
}
std::uint64_t checksum(std::uint64_t inputs, std::span<const std::uint8_t> answers) {
    fnv1a h;
    h.h = inputs;
    h.add(std::string("any"));
    h.add(std::uint32_t(answers.size())), h.add(std::uint32_t(std::uint64_t(answers.size()) >> 32));
    for (const std::uint8_t a : answers) h.add(std::uint32_t(a));
    return h.h;
}

std::string hex(std::uint64_t v) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
    return text;
}

enum class cached { usable, rejected };

// Loads a cached answer file and checks it: the right count, the checksum its name holds (none: a file
// from before the race kept one), and the sample traced again agrees. Says why on stdout when it cannot
// be used.
template <class Answer, class Read, class Trace, class Same>
cached load(const std::filesystem::path& f, std::uint64_t inputs, std::optional<std::uint64_t> sum,
            std::span<const ray> rays, std::vector<Answer>& out, Read read, Trace trace, Same agree) {
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
    if (!sum) {
        std::cout << "  reference cache: '" << f.string() << "' has no checksum in its name (written by an "
                  << "older race); tracing again\n";
        return cached::rejected;
    }
    if (const std::uint64_t got = checksum(inputs, std::span<const Answer>(out)); got != *sum) {
        std::cout << "  reference cache: '" << f.string() << "' does not match the checksum in its name (its "
                  << "answers give " << hex(got) << "): corrupt, or altered since it was written; tracing again\n";
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

// The cache's files for one answer set: PREFIX_SUM.EXT (SUM: the answers' checksum) and, from races before
// the checksum, PREFIX.EXT; each with its checksum, if any. Sorted, so that the order does not depend on
// the folder's.
std::vector<std::pair<std::filesystem::path, std::optional<std::uint64_t>>> candidates(
    const std::filesystem::path& folder, const std::string& prefix, const std::string& ext) {
    std::vector<std::pair<std::filesystem::path, std::optional<std::uint64_t>>> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = e.path().filename().string();
        if (name.size() < prefix.size() + ext.size() || name.compare(0, prefix.size(), prefix) != 0 ||
            !name.ends_with(ext))
            continue;
        const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - ext.size());
        if (middle.empty()) {
            out.emplace_back(e.path(), std::nullopt);
        } else if (middle.size() == 17 && middle[0] == '_' &&
                   middle.find_first_not_of("0123456789abcdef", 1) == std::string::npos) {
            out.emplace_back(e.path(), std::stoull(middle.substr(1), nullptr, 16));
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

reference_cache::reference_cache(std::filesystem::path folder, const scene& s, const accel& exact, int threads)
    : folder_(std::move(folder)), exact_(exact), threads_(threads) {
    // The file names start with the scene's name, made safe for a file name.
    stem_ = std::filesystem::path(s.name).stem().string();
    for (char& c : stem_)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    if (stem_.empty()) stem_ = "scene";
    fnv1a h;
    h.add(std::string("strahl brute-force reference, format 1"));
    if (exact.name() != "brute") {
        stem_ += "_" + exact.name();
        h.add(exact.name());
    }
    h.add(std::uint32_t(s.mesh.triangle_count()));
    for (std::size_t i = 0; i < s.mesh.triangle_count(); ++i)
        for (const vec3& v : s.mesh.triangle(i)) h.add(v);
    scene_hash_ = h.h;
}

std::string reference_cache::prefix(const std::string& set, const char* query, std::span<const ray> rays,
                                    std::uint64_t& inputs) const {
    fnv1a h;
    h.h = scene_hash_;
    h.add(std::string(query));
    h.add(std::uint32_t(rays.size()));
    for (const ray& r : rays) h.add(r.org), h.add(r.tmin), h.add(r.dir), h.add(r.tmax);
    inputs = h.h;
    return stem_ + "_" + set + "_" + query + "_" + hex(inputs);
}

// The answers from a file when one is usable; else traced, and written through a temporary file and a
// rename, so that an interrupted run leaves no half-written file. Files that were there but unusable are
// removed. A cache that cannot be written is no error: the race says so once and goes on without it.
template <class Answer, class Read, class Write, class Trace, class Same>
std::vector<Answer> reference_cache::answers(const std::string& set, const char* query, std::span<const ray> rays,
                                             Read read, Write write, Trace trace, Same agree) {
    std::vector<Answer> out;
    std::uint64_t inputs = 0;
    const std::string name = folder_.empty() ? std::string() : prefix(set, query, rays, inputs);
    const std::string ext = query[0] == 'c' ? ".hits" : ".flags";
    if (!folder_.empty()) {
        bool rejected = false;
        for (const auto& [f, sum] : candidates(folder_, name, ext)) {
            if (load(f, inputs, sum, rays, out, read, trace, agree) == cached::usable) {
                // Touched: the file was used now (prune_reference_cache removes the least recently used).
                std::error_code ec;
                std::filesystem::last_write_time(f, std::filesystem::file_time_type::clock::now(), ec);
                ++loaded_;
                return out;
            }
            rejected = true;
            std::error_code ec;
            std::filesystem::remove(f, ec);
        }
        stale_ += rejected;
    }
    out.assign(rays.size(), Answer{});
    trace(rays, out);
    ++traced_;
    if (folder_.empty()) return out;
    const std::filesystem::path f = folder_ / (name + "_" + hex(checksum(inputs, std::span<const Answer>(out))) + ext);
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
    // The cache's own files: NAME_SET_QUERY_HASH_SUM.hits or .flags (answers() above), perhaps with .tmp after
    // it, and NAME_SET_QUERY_HASH.hits or .flags, as races wrote them before the checksum.
    static const std::regex ours(R"(.+_(closest|any)_[0-9a-f]{16}(_[0-9a-f]{16})?\.(hits|flags)(\.tmp)?)");
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
