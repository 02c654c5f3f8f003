// Helpers for the course's tests: where the shared meshes and test data are, and a scratch folder.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <string>

namespace strahl::test {

// (The sanitizer run, the asan preset, runs every check at the size the release run does: no test thins
// itself there.)

// ../shared/scenes/<name>, or an empty path when the course's shared meshes are not beside this clone
// (a user's own clone): callers SKIP-style return with a WARN naming what was skipped.
inline std::filesystem::path shared_scene(const std::string& name) {
    const std::filesystem::path p = std::filesystem::path(STRAHL_SHARED_SCENES) / name;
    std::error_code ec;
    return std::filesystem::exists(p, ec) ? p : std::filesystem::path();
}

// tests/data/<name>: small files checked into the repository.
inline std::filesystem::path data_file(const std::string& name) { return std::filesystem::path(STRAHL_TEST_DATA) / name; }

// A fresh, empty scratch folder under the build tree, unique per name; under $STRAHL_TEST_TMP where that is
// set (./course's grading and solo checks run several binaries of one chapter's tests at once, each with its own).
inline std::filesystem::path scratch_dir(const std::string& name) {
    const char* own = std::getenv("STRAHL_TEST_TMP");
    const std::filesystem::path p = std::filesystem::path(own && *own ? own : STRAHL_TEST_TMP) / name;
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p;
}

}  // namespace strahl::test
