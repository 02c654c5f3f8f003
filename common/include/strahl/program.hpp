// What every program of the course shares: command-line options with --help, an error policy, and the
// rule that nothing the user wrote is overwritten without being asked.
#pragma once
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace strahl {

struct scene;

// A wrong command line: unknown option, missing or malformed value. Programs print it with the usage.
class usage_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A tiny option parser: --name VALUE, --name=VALUE and --flag. --help is always there.
class cli {
public:
    cli(std::string program, std::string summary);

    cli& flag(const std::string& name, const std::string& help);
    cli& option(const std::string& name, const std::string& value_name, const std::string& default_value,
                const std::string& help);

    // Returns false when --help was given (usage already printed to stdout): the program exits 0.
    // Throws usage_error on anything it does not understand.
    bool parse(int argc, const char* const* argv);

    bool has(const std::string& flag_name) const;     // a flag given, or an option given explicitly
    std::string get(const std::string& name) const;   // the option's value or its default
    int get_int(const std::string& name) const;       // throws usage_error if not an integer
    double get_double(const std::string& name) const;  // throws usage_error if not a finite number
    std::string usage() const;

private:
    struct entry {
        std::string name, value_name, default_value, help;
        bool is_flag;
    };
    const entry& find(const std::string& name) const;
    std::string program_, summary_;
    std::vector<entry> entries_;
    std::map<std::string, std::string> values_;
};

// Runs body(), the program's real main, and turns exceptions into one clear line on stderr and an exit code:
// 2 for a usage error (with a pointer to --help), 3 for an exercise not done yet, 1 for any other error.
int guarded_main(const char* program, int (*body)(int, const char* const*), int argc, const char* const* argv);

// Prepares to write `file`: creates its folder and refuses (std::runtime_error) to replace an existing file
// the user named themselves (user_named) unless force is set. Files in the course's own out/ folders are
// the course's to regenerate. Also fails early, with a clear message, when the folder cannot be written.
void prepare_output(const std::filesystem::path& file, bool user_named, bool force);

// --width and --height as the chapter programs read them: the width from --width or default_width, the
// height from --height or 3/4 of the width; both in [1, max_side], else usage_error.
struct image_size {
    int width = 0, height = 0;
};
image_size read_image_size(const cli& args, int default_width, int max_side);

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
// Field k of a row as a finite number >= 0; throws std::runtime_error naming the file and line otherwise.
double csv_number(const std::filesystem::path& file, const csv_row& row, std::size_t k);
// A text for one CSV field: as it is, or in double quotes (quotes doubled) where it holds a comma, a quote or
// a line break, so that read_csv gives it back whole.
std::string csv_field(const std::string& text);

// One of the course's shared meshes (file, in ../shared/scenes beside the clone), loaded and named `name`
// for the chapter programs; where it is absent (a clone of its own), prints "NAME: skipped, ..." and
// returns nothing. A mesh that is there but cannot be read throws, as load_scene does.
std::optional<scene> load_shared_mesh(const std::string& file, const std::string& name);

}  // namespace strahl
