// What every program of the course shares: command-line options with --help, an error policy, and the
// rule that nothing the user wrote is overwritten without being asked.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace strahl {

struct scene;

// The track a chapter's program was linked with, "solutions" or "exercises": the program links one of
// common/track/solutions.cpp and common/track/exercises.cpp, so one compiled main.cpp serves both tracks.
const char* track_name();

// A wrong command line: unknown option, missing or malformed value. Programs print it with the usage.
class usage_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The command line of every program: --name VALUE, --name=VALUE and --flag, parsed by CLI11 (Debian's
// libcli11-dev); this class only keeps the course's conventions around it: options read as text and
// checked when read (get_int, get_double: the message names the option), the last of a repeated option
// wins, every error a usage_error (exit 2), and --help printing the same usage text in every program.
class cli {
public:
    cli(std::string program, std::string summary);
    cli(cli&&) noexcept;
    cli& operator=(cli&&) noexcept;
    ~cli();

    cli& flag(const std::string& name, const std::string& help);
    cli& option(const std::string& name, const std::string& value_name, const std::string& default_value,
                const std::string& help);

    // Returns false when --help was given (usage already printed to stdout): the program exits 0.
    // Throws usage_error on anything it does not understand.
    bool parse(int argc, const char* const* argv);

    bool has(const std::string& flag_name) const;     // a flag given, or an option given explicitly
    std::string get(const std::string& name) const;   // the option's value or its default
    int get_int(const std::string& name) const;       // throws usage_error if not an integer
    double get_double(const std::string& name) const;  // throws usage_error if not a finite number (subnormals
                                                       // are numbers; 1e999 and 1e-999 are out of range)
    std::string usage() const;

    // The options most programs share, in the same words everywhere: --out DIR (out_help says what goes
    // there) with --force (replace files in a folder named with --out); --threads N (help as given, its
    // range stated by read_threads); --scene NAME, one of `offered` or all (the names in `all`).
    cli& output_options(const std::string& out_help);
    cli& threads_option(const std::string& default_value, const std::string& help);
    cli& scene_option(const std::vector<std::string>& offered, const std::vector<std::string>& all,
                      const std::string& note = "");
    // --scene as scene_option declared it: the names chosen ("all": those in `all`, in their order; a
    // program whose "all" depends on other options passes its own), else usage_error naming the choices
    // ("--scene must be stadium, bunny, sponza or all, not 'x'").
    std::vector<std::string> scene_names() const;
    std::vector<std::string> scene_names(const std::vector<std::string>& all) const;

private:
    struct entry {
        std::string name, value_name, default_value, help;
        bool is_flag;
    };
    struct parser;  // CLI11's App, kept out of this header (CLI11 is a large header-only library)
    const entry& find(const std::string& name) const;
    std::string program_, summary_;
    std::vector<entry> entries_;
    std::unique_ptr<parser> parser_;
    std::vector<std::string> scene_offered_, scene_all_;  // scene_option's lists
};

// Runs body(), the program's real main, and turns exceptions into one clear line on stderr and an exit code:
// 2 for a usage error (with a pointer to --help), 3 for an exercise not done yet, 1 for any other error.
int guarded_main(const char* program, int (*body)(int, const char* const*), int argc, const char* const* argv);

// Prepares to write `file`: creates its folder and refuses (std::runtime_error) to replace an existing file
// the user named themselves (user_named) unless force is set. Files in the course's own out/ folders are
// the course's to regenerate. Also fails early, with a clear message, when the folder cannot be written,
// when an existing file cannot be (read-only: found before the work, not after it), and when `file` is a
// symbolic link to nothing (writing would create its target somewhere the user did not name).
void prepare_output(const std::filesystem::path& file, bool user_named, bool force);

// Writes text (a CSV table, an SVG) to file, replacing it; throws std::runtime_error naming the file if it
// cannot (call prepare_output first for the user's files).
void write_text(const std::filesystem::path& file, const std::string& text);

// The most threads --threads takes. TBB and Embree set up state per thread they are allowed, so an
// unbounded count (--threads 2147483647) allocates until memory runs out; 1024 is far above any machine
// the course runs on.
constexpr int max_threads = 1024;

// --threads as the programs read it: an integer in [lo, max_threads] (lo = 0 where 0 means one thread per
// core), else usage_error naming the range and this machine's hardware threads.
int read_threads(const cli& args, int lo);

// A scene of the chapter programs by its short name: teapot, stadium (the teapot in a stadium) and the other
// built-in scenes, or bunny, armadillo, ogre, sponza: the course's shared meshes (nothing where they are
// absent, as load_shared_mesh says).
std::optional<scene> course_scene(const std::string& name);

// Bytes of memory this process can still use: /proc/meminfo's MemAvailable (the physical memory where
// that is missing), or the container's memory limit (cgroup) where that is less. The environment variable
// STRAHL_MEMORY_LIMIT_MB, where set, caps it (to keep a run small, and for the tests).
std::uint64_t available_memory();

// Refuses (std::runtime_error) to start work that needs more than available_memory(): "WHAT: about N GiB
// of memory needed, but only M GiB available". Called before allocating, with an estimate that errs
// large, so that a too-large image is refused at once instead of running the machine out of memory.
void check_memory(std::uint64_t bytes, const std::string& what);

// --width and --height as the chapter programs read them: the width from --width or default_width, the
// height from --height or 3/4 of the width; both in [1, max_side], else usage_error. With bytes_per_pixel
// (what the program holds per pixel at most, an estimate), also check_memory for width x height pixels.
struct image_size {
    int width = 0, height = 0;
};
image_size read_image_size(const cli& args, int default_width, int max_side, std::uint64_t bytes_per_pixel = 0);

// A comma-separated list of integers in [lo, hi] for option --name ("4,16,64"); throws usage_error on
// anything else, or on an empty list.
std::vector<int> parse_int_list(const std::string& text, const std::string& name, int lo, int hi);

// --replot: a CSV file a program wrote earlier, read back. Its first line must be `header` exactly (else the
// error says it is not `what`, e.g. "a bins.csv written by ch05"); every other non-empty line must have as
// many comma-separated fields (a field in double quotes may hold commas and line breaks; "" is a quote inside
// it, as RFC 4180 writes them). Throws std::runtime_error naming the file and line otherwise, or if no row.
struct csv_row {
    int line = 0;  // the line number in the file, for messages
    std::vector<std::string> cells;
};
std::vector<csv_row> read_csv(const std::filesystem::path& file, const std::string& header, const std::string& what);
// The same for a format that grew columns at its end: the first line is `header`, or `header` followed by
// ",tail" (the later version's columns); each row has as many fields as its file's first line.
std::vector<csv_row> read_csv(const std::filesystem::path& file, const std::string& header, const std::string& tail,
                              const std::string& what);
// Field k of a row as a finite number >= 0 (subnormals included); throws std::runtime_error naming the file
// and line otherwise, saying "out of range" for numbers no double holds (1e999, 1e-999).
double csv_number(const std::filesystem::path& file, const csv_row& row, std::size_t k);
// A text for one CSV field: as it is, or in double quotes (quotes doubled) where it holds a comma, a quote or
// a line break, so that read_csv gives it back whole.
std::string csv_field(const std::string& text);

// One of the course's shared meshes (file, in ../shared/scenes beside the clone), loaded and named `name`
// for the chapter programs; where it is absent (a clone of its own), prints "NAME: skipped, ..." and
// returns nothing. A mesh that is there but cannot be read throws, as load_scene does.
std::optional<scene> load_shared_mesh(const std::string& file, const std::string& name);

}  // namespace strahl
