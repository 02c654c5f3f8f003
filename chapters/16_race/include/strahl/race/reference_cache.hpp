// The brute-force reference, remembered on disk. Brute force tests every ray against every triangle: on
// Sponza (262,205 triangles) one pass over the race's 27,648 rays of a set takes about half a minute on two
// cores, and a race run again on the same scene and rays needs the very same answers. So each answer set is
// kept in a file named by a 64-bit hash (FNV-1a) of the triangles' vertices and of the rays, bit for bit,
// and by a checksum of its answers (FNV-1a over that hash and every answer), in the race's hit and flag
// formats (ray_io.hpp): NAME_SET_QUERY_HASH_CHECKSUM.hits or .flags.
//
// A cached file is never trusted blindly. On loading, its answers must give the checksum in its name: a
// file corrupted or altered in any record after it was written (or written for other inputs and renamed)
// is traced again and replaced, saying so. Then a sample of its rays (evenly spread over the set and over
// the rays it says hit) is traced again by brute force and must agree bit for bit: a changed triangle test
// or a file from another build shows as a stale file, which is traced again and replaced. (A change to the
// triangle test that alters none of the sampled rays would slip through: delete the folder to be sure, or
// run the race with --no-cache.) Files from races before the checksum, named without one, are traced again.
#pragma once
#include "strahl/race/brute_force.hpp"
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace strahl::race {

class reference_cache {
public:
    // `folder`: where the files go (created when first needed); empty: no cache, every answer traced.
    // `exact` (brute force, or brute force with another triangle test: an oracle) must have been built on
    // `s`; `threads` trace the reference. An oracle other than "brute" has its name in the file names and
    // in the hash, so the answers of two triangle tests never mix.
    reference_cache(std::filesystem::path folder, const scene& s, const accel& exact, int threads);

    // The answers of brute force for `rays` (`set` names them in the file name, for people reading the
    // folder): from the cache when a file is there, its checksum holds and its sample agrees, else traced
    // and stored.
    std::vector<hit> closest(const std::string& set, std::span<const ray> rays);
    std::vector<std::uint8_t> any(const std::string& set, std::span<const ray> rays);

    // Rays re-traced to check each cached file: this many spread over the set, and as many again over the
    // rays the file says hit (fewer when there are fewer).
    static constexpr std::size_t audit_rays = 128;

    // Answer sets so far: read from usable files, traced by brute force, and of those traced, how many
    // replaced a file that was there but unusable (corrupt, failing its checksum, or stale).
    int loaded() const { return loaded_; }
    int traced() const { return traced_; }
    int stale() const { return stale_; }

private:
    // NAME_SET_QUERY_HASH, the start of the answer set's file name; `inputs` gets HASH, of the scene's
    // triangles, the query and the rays.
    std::string prefix(const std::string& set, const char* query, std::span<const ray> rays,
                       std::uint64_t& inputs) const;
    template <class Answer, class Read, class Write, class Trace, class Same>
    std::vector<Answer> answers(const std::string& set, const char* query, std::span<const ray> rays, Read read,
                                Write write, Trace trace, Same agree);

    std::filesystem::path folder_;
    std::string stem_;
    std::uint64_t scene_hash_ = 0;
    const accel& exact_;
    int threads_ = 1, loaded_ = 0, traced_ = 0, stale_ = 0;
};

// What prune_reference_cache removed.
struct pruned_files {
    int files = 0;
    std::uintmax_t bytes = 0;
};

// Keeps a cache folder within max_bytes. Every use of a file touches it, so the files least recently used
// have the oldest modification times: those go first, oldest first, until the folder's answer files add up
// to max_bytes or less. Files used or written since `since` (this run's) are never removed, even over the
// limit, and neither is any file whose name is not one the cache writes (NAME_SET_QUERY_HASH_CHECKSUM.hits
// or .flags, the same without _CHECKSUM as older races wrote them, or such a name with .tmp after it).
pruned_files prune_reference_cache(const std::filesystem::path& folder, std::uintmax_t max_bytes,
                                   std::filesystem::file_time_type since);

}  // namespace strahl::race
