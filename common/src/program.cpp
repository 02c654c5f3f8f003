#include "strahl/program.hpp"
#include "strahl/procedural.hpp"
#include "strahl/scene.hpp"
#include "strahl/todo.hpp"
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace strahl {

namespace {
// "--name". (Spelled out rather than dashed(name), which trips a false -Wrestrict in g++ 12, PR 105329.)
std::string dashed(const std::string& name) {
    std::string s = "--";
    s += name;
    return s;
}

// A whole text read as one double, as strtod reads it. A subnormal (4e-320) is a number like any other;
// a number beyond what a double holds (1e999, or 1e-999, which would round to 0) is out_of_range, so that
// the messages can say so rather than "not a number". "inf" and "nan" are not finite: not_a_number.
enum class number_read { ok, not_a_number, out_of_range };
number_read read_double(const std::string& text, double& v) {
    if (text.empty()) return number_read::not_a_number;
    char* end = nullptr;
    errno = 0;
    v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || end != text.c_str() + text.size()) return number_read::not_a_number;
    // strtod sets ERANGE on overflow (+-HUGE_VAL), on underflow to zero, and (glibc) on a subnormal result,
    // which is still the nearest double and is kept.
    if (errno == ERANGE && (std::isinf(v) || v == 0.0)) return number_read::out_of_range;
    if (!std::isfinite(v)) return number_read::not_a_number;
    return number_read::ok;
}

std::string bytes_text(std::uint64_t bytes) {
    char text[32];
    if (bytes >= (std::uint64_t(1) << 30)) std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1 << 30));
    else std::snprintf(text, sizeof text, "%.0f MiB", double(bytes) / double(1 << 20));
    return text;
}
}  // namespace

struct cli::parser {
    CLI::App app;
};

cli::cli(std::string program, std::string summary)
    : program_(std::move(program)), summary_(std::move(summary)), parser_(std::make_unique<parser>()) {
    parser_->app.name(program_);
    parser_->app.description(summary_);
    parser_->app.set_help_flag();   // --help is an entry of ours, printed by usage()
    parser_->app.allow_extras(true);  // what CLI11 does not take is named below, as the course words it
    flag("help", "print this help and exit");
}
cli::cli(cli&&) noexcept = default;
cli& cli::operator=(cli&&) noexcept = default;
cli::~cli() = default;

cli& cli::flag(const std::string& name, const std::string& help) {
    entries_.push_back({name, "", "", help, true});
    parser_->app.add_flag(dashed(name))->description(help)->disable_flag_override();
    return *this;
}

cli& cli::option(const std::string& name, const std::string& value_name, const std::string& default_value,
                 const std::string& help) {
    entries_.push_back({name, value_name, default_value, help, false});
    parser_->app.add_option(dashed(name), help)->type_name(value_name)->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    return *this;
}

cli& cli::output_options(const std::string& out_help) {
    option("out", "DIR", "", out_help);
    return flag("force", "replace existing files in a folder named with --out");
}

cli& cli::threads_option(const std::string& default_value, const std::string& help) {
    return option("threads", "N", default_value, help);
}

namespace {
// "a, b or c" (last: "c"); "a, b" where last is empty.
std::string listed(const std::vector<std::string>& names, const std::string& last) {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) text += (i == 0 ? "" : ", ") + names[i];
    return text + (names.empty() || last.empty() ? "" : " or ") + last;
}
}  // namespace

cli& cli::scene_option(const std::vector<std::string>& offered, const std::vector<std::string>& all,
                       const std::string& note) {
    scene_offered_ = offered, scene_all_ = all;
    return option("scene", "NAME", "all", listed(offered, "all") + " (all: " + listed(all, "") + (note.empty() ? "" : "; " + note) + ")");
}

std::vector<std::string> cli::scene_names() const { return scene_names(scene_all_); }

std::vector<std::string> cli::scene_names(const std::vector<std::string>& all) const {
    const std::string which = get("scene");
    if (which == "all") return all;
    if (std::find(scene_offered_.begin(), scene_offered_.end(), which) == scene_offered_.end())
        throw usage_error("--scene must be " + listed(scene_offered_, "all") + ", not '" + which + "'");
    return {which};
}

std::optional<scene> course_scene(const std::string& name) {
    for (const auto& [short_name, file] : {std::pair{"bunny", "bunny.ply"}, std::pair{"armadillo", "armadillo.obj"},
                                           std::pair{"ogre", "ogre.obj"}, std::pair{"sponza", "sponza.obj"}})
        if (name == short_name) return load_shared_mesh(file, name);
    return builtin_scene(name == "stadium" ? "teapot_stadium" : name);
}

const cli::entry& cli::find(const std::string& name) const {
    for (const entry& e : entries_)
        if (e.name == name) return e;
    throw usage_error("unknown option --" + name);
}

bool cli::parse(int argc, const char* const* argv) {
    try {
        parser_->app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // CLI11's words for a flag given a value ("quick was given a disallowed flag override") and an
        // option without one ("--width: 1 required W missing"), in the course's.
        const std::string what = error.what();
        for (const entry& e : entries_) {
            if (e.is_flag && what.rfind(e.name + " was given", 0) == 0) throw usage_error(dashed(e.name) + " takes no value");
            if (!e.is_flag && what.rfind(dashed(e.name) + ":", 0) == 0)
                throw usage_error(dashed(e.name) + " needs a value (" + e.value_name + ")");
        }
        throw usage_error(what);
    }
    // The first argument CLI11 did not take: an unknown option or a stray word.
    if (const std::vector<std::string> extra = parser_->app.remaining(); !extra.empty()) {
        if (extra[0].rfind("--", 0) != 0 || extra[0].size() == 2) throw usage_error("unexpected argument '" + extra[0] + "'");
        throw usage_error("unknown option " + extra[0].substr(0, extra[0].find('=')));
    }
    if (has("help")) {
        std::cout << usage();
        return false;
    }
    return true;
}

bool cli::has(const std::string& name) const {
    find(name);
    return parser_->app.get_option(dashed(name))->count() != 0;
}

std::string cli::get(const std::string& name) const {
    const entry& e = find(name);
    if (e.is_flag) return has(name) ? "1" : "";  // flags read as "1"
    const CLI::Option* o = parser_->app.get_option(dashed(name));
    return o->count() != 0 ? o->as<std::string>() : e.default_value;
}

int cli::get_int(const std::string& name) const {
    const std::string s = get(name);
    std::size_t used = 0;
    long v = 0;
    bool too_large = false;
    try {
        v = std::stol(s, &used);
    } catch (const std::out_of_range&) {
        too_large = true;
    } catch (const std::exception&) {
        used = 0;
    }
    if (too_large || (used == s.size() && (v < -2147483647L || v > 2147483647L)))
        throw usage_error(dashed(name) + " expects an integer, got '" + s + "', out of range (at most 2147483647 in size)");
    if (used != s.size() || s.empty()) throw usage_error(dashed(name) + " expects an integer, got '" + s + "'");
    return int(v);
}

double cli::get_double(const std::string& name) const {
    const std::string s = get(name);
    double v = 0.0;
    switch (read_double(s, v)) {
        case number_read::ok: return v;
        case number_read::out_of_range:
            throw usage_error(dashed(name) + " expects a finite number, got '" + s + "', out of range for a double");
        case number_read::not_a_number: break;
    }
    throw usage_error(dashed(name) + " expects a finite number, got '" + s + "'");
}

std::string cli::usage() const {
    std::ostringstream out;
    out << "usage: " << program_ << " [options]\n\n" << summary_ << "\n\noptions:\n";
    for (const entry& e : entries_) {
        std::string left = "  --";
        left += e.name;
        if (!e.is_flag) left.append(" ").append(e.value_name);
        if (left.size() < 28) left.resize(28, ' ');
        else left.append("\n").append(28, ' ');
        out << left << e.help;
        if (!e.is_flag && !e.default_value.empty()) out << " (default: " << e.default_value << ")";
        out << "\n";
    }
    return out.str();
}

int guarded_main(const char* program, int (*body)(int, const char* const*), int argc, const char* const* argv) {
    try {
        return body(argc, argv);
    } catch (const usage_error& e) {
        std::cerr << program << ": " << e.what() << " (see " << program << " --help)\n";
        return 2;
    } catch (const not_implemented& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return 3;
    } catch (const std::exception& e) {
        std::cerr << program << ": error: " << e.what() << "\n";
        return 1;
    }
}

void write_text(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write '" + file.string() + "': " + std::strerror(errno));
    out << text;
    out.close();
    if (!out) throw std::runtime_error("writing '" + file.string() + "' failed");
}

void prepare_output(const std::filesystem::path& file, bool user_named, bool force) {
    namespace fs = std::filesystem;
    if (file.empty()) throw std::runtime_error("empty output path");
    std::error_code ec;
    if (fs::is_directory(file, ec)) throw std::runtime_error("cannot write '" + file.string() + "': it is a folder");
    // A link to nothing: writing would create its target, wherever it points, a file the user never named.
    if (fs::is_symlink(fs::symlink_status(file, ec)) && !fs::exists(file, ec))
        throw std::runtime_error("'" + file.string() + "' is a symbolic link to '" + fs::read_symlink(file, ec).string() +
                                 "', which does not exist; not writing through it (remove the link, or name the "
                                 "file it should point to)");
    const bool exists = fs::exists(file, ec);
    if (user_named && !force && exists)
        throw std::runtime_error("'" + file.string() + "' exists; not overwriting it (pass --force to replace it)");
    // An existing file that cannot be written (read-only) would fail only after the work: found now.
    if (exists && access(file.c_str(), W_OK) != 0)
        throw std::runtime_error("cannot replace '" + file.string() + "': " + std::strerror(errno) +
                                 " (the file is read-only?)");
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    fs::create_directories(folder, ec);
    if (!fs::is_directory(folder))
        throw std::runtime_error("cannot create folder '" + folder.string() + "' for '" + file.string() + "'" +
                                 (ec ? ": " + ec.message() : std::string()));
    if (access(folder.c_str(), W_OK) != 0)
        throw std::runtime_error("cannot write into folder '" + folder.string() + "' (permission denied)");
}

int read_threads(const cli& args, int lo) {
    const int n = args.get_int("threads");
    if (n < lo || n > max_threads)
        throw usage_error("--threads must lie in [" + std::to_string(lo) + ", " + std::to_string(max_threads) + "]" +
                          (lo == 0 ? " (0: one per core)" : "") + ", not " + std::to_string(n) + "; this machine has " +
                          std::to_string(std::thread::hardware_concurrency()) + " hardware threads");
    return n;
}

std::uint64_t available_memory() {
    constexpr std::uint64_t unknown = std::numeric_limits<std::uint64_t>::max();
    std::uint64_t bytes = 0;
    std::ifstream meminfo("/proc/meminfo");
    for (std::string key; meminfo >> key;) {
        std::uint64_t kib = 0;
        if (key == "MemAvailable:" && meminfo >> kib) {
            bytes = kib * 1024;
            break;
        }
        meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    }
    if (bytes == 0) {
        const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
        bytes = pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : unknown;
    }
    // In a container MemAvailable is the host's; the container's own limit (cgroup v2, else v1) may be less.
    // (Its limit, not the limit less its use: the use counts page cache the kernel would give back.)
    for (const char* limit_file : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
        std::ifstream limit_in(limit_file);
        std::uint64_t limit = 0;
        if (limit_in >> limit) {  // "max", no limit, reads as no number
            bytes = std::min(bytes, limit);
            break;
        }
    }
    if (const char* env = std::getenv("STRAHL_MEMORY_LIMIT_MB")) {
        char* end = nullptr;
        const unsigned long long mb = std::strtoull(env, &end, 10);
        if (*env == 0 || *end != 0 || mb > (unknown >> 20))
            throw std::runtime_error(std::string("STRAHL_MEMORY_LIMIT_MB must be a whole number of megabytes, not '") +
                                     env + "'");
        bytes = std::min<std::uint64_t>(bytes, mb << 20);
    }
    return bytes;
}

void check_memory(std::uint64_t bytes, const std::string& what) {
    const std::uint64_t available = available_memory();
    if (bytes > available)
        throw std::runtime_error(what + ": about " + bytes_text(bytes) + " of memory needed, but only " +
                                 bytes_text(available) + " available");
}

image_size read_image_size(const cli& args, int default_width, int max_side, std::uint64_t bytes_per_pixel) {
    image_size size;
    size.width = args.has("width") ? args.get_int("width") : default_width;
    size.height = args.has("height") ? args.get_int("height") : size.width * 3 / 4;
    if (size.width < 1 || size.width > max_side || size.height < 1 || size.height > max_side)
        throw usage_error("--width and --height must lie in [1, " + std::to_string(max_side) + "]");
    if (bytes_per_pixel > 0)
        check_memory(std::uint64_t(size.width) * std::uint64_t(size.height) * bytes_per_pixel,
                     "a " + std::to_string(size.width) + " x " + std::to_string(size.height) + " image");
    return size;
}

std::vector<int> parse_int_list(const std::string& text, const std::string& name, int lo, int hi) {
    std::vector<int> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        char* end = nullptr;
        const long k = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != 0 || k < lo || k > hi)
            throw usage_error("--" + name + " wants numbers in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                              "], not '" + item + "'");
        out.push_back(int(k));
    }
    if (out.empty()) throw usage_error("--" + name + " wants at least one number");
    return out;
}

namespace {
// A CSV line's fields, as RFC 4180 quotes them: a field in double quotes may hold commas, and "" stands for
// one quote inside it. Returns nothing for a quote left open or text after a closing quote.
std::optional<std::vector<std::string>> split_fields(const std::string& line) {
    std::vector<std::string> cells(1);
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == ',') {
            cells.emplace_back();
        } else if (c == '"' && cells.back().empty()) {  // a quoted field: up to the unpaired closing quote
            for (++i;; ++i) {
                if (i >= line.size()) return std::nullopt;
                if (line[i] != '"') cells.back() += line[i];
                else if (i + 1 < line.size() && line[i + 1] == '"') cells.back() += line[++i];
                else break;
            }
            if (i + 1 < line.size() && line[i + 1] != ',') return std::nullopt;
        } else {
            cells.back() += c;
        }
    }
    return cells;
}
}  // namespace

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + '"';
}

std::vector<csv_row> read_csv(const std::filesystem::path& file, const std::string& header, const std::string& what) {
    return read_csv(file, header, "", what);
}

std::vector<csv_row> read_csv(const std::filesystem::path& file, const std::string& header, const std::string& tail,
                              const std::string& what) {
    std::ifstream f(file);
    if (!f) throw std::runtime_error("cannot read '" + file.string() + "'");
    std::string line;
    const std::string longer = tail.empty() ? header : header + "," + tail;
    if (!std::getline(f, line) || (line != header && line != longer))
        throw std::runtime_error("'" + file.string() + "' is not " + what + " (its first line should be '" + longer +
                                 "'" + (tail.empty() ? "" : ", or '" + header + "' in files written before its last columns") +
                                 ")");
    const std::size_t fields = split_fields(line).value().size();
    std::vector<csv_row> rows;
    for (int number = 2; std::getline(f, line); number += 1 + int(std::count(line.begin(), line.end(), '\n'))) {
        if (line.empty()) continue;
        std::optional<std::vector<std::string>> cells = split_fields(line);
        // A quoted field may run over line breaks: the row goes on on the next line.
        for (std::string more; !cells && std::getline(f, more);) cells = split_fields(line += "\n" + more);
        if (!cells)
            throw std::runtime_error(file.string() + ", line " + std::to_string(number) +
                                     ": a quoted field is not closed, or text follows its closing quote");
        csv_row r{number, std::move(*cells)};
        if (r.cells.size() != fields)
            throw std::runtime_error(file.string() + ", line " + std::to_string(number) + ": " +
                                     std::to_string(fields) + " fields expected, not " + std::to_string(r.cells.size()));
        rows.push_back(std::move(r));
    }
    if (rows.empty()) throw std::runtime_error("'" + file.string() + "' holds no rows");
    return rows;
}

double csv_number(const std::filesystem::path& file, const csv_row& row, std::size_t k) {
    const std::string& cell = row.cells.at(k);
    double v = 0.0;
    const number_read r = read_double(cell, v);
    const std::string where = file.string() + ", line " + std::to_string(row.line) + ": '" + cell + "'";
    if (r == number_read::out_of_range)
        throw std::runtime_error(where + " is out of range: no double holds it (they lie within about 4.9e-324 "
                                         "to 1.8e308)");
    if (r != number_read::ok || v < 0.0) throw std::runtime_error(where + " is not a number >= 0");
    return v;
}

std::optional<scene> load_shared_mesh(const std::string& file, const std::string& name) {
    const std::filesystem::path p = std::filesystem::path(STRAHL_SHARED_SCENES) / file;
    std::error_code ec;
    if (!std::filesystem::exists(p, ec)) {
        std::printf("%s: skipped, %s is not there (the course's shared meshes)\n", name.c_str(), p.string().c_str());
        return std::nullopt;
    }
    scene s = load_scene(p);
    s.name = name;
    return s;
}

}  // namespace strahl
