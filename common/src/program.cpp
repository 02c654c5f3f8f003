#include "strahl/program.hpp"
#include "strahl/scene.hpp"
#include "strahl/todo.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace strahl {

namespace {
// "--name". (Spelled out rather than dashed(name), which trips a false -Wrestrict in g++ 12, PR 105329.)
std::string dashed(const std::string& name) {
    std::string s = "--";
    s += name;
    return s;
}
}  // namespace

cli::cli(std::string program, std::string summary) : program_(std::move(program)), summary_(std::move(summary)) {
    flag("help", "print this help and exit");
}

cli& cli::flag(const std::string& name, const std::string& help) {
    entries_.push_back({name, "", "", help, true});
    return *this;
}

cli& cli::option(const std::string& name, const std::string& value_name, const std::string& default_value,
                 const std::string& help) {
    entries_.push_back({name, value_name, default_value, help, false});
    return *this;
}

const cli::entry& cli::find(const std::string& name) const {
    for (const entry& e : entries_)
        if (e.name == name) return e;
    throw usage_error("unknown option --" + name);
}

bool cli::parse(int argc, const char* const* argv) {
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg.rfind("--", 0) != 0 || arg.size() == 2) throw usage_error("unexpected argument '" + arg + "'");
        arg = arg.substr(2);
        std::string value;
        bool has_value = false;
        if (const auto eq = arg.find('='); eq != std::string::npos) {
            value = arg.substr(eq + 1);
            arg = arg.substr(0, eq);
            has_value = true;
        }
        const entry& e = find(arg);
        if (e.is_flag) {
            if (has_value) throw usage_error(dashed(arg) + " takes no value");
            values_.insert_or_assign(arg, std::string(1, '1'));  // flags read as "1"
            continue;
        }
        if (!has_value) {
            if (i + 1 >= argc) throw usage_error(dashed(arg) + " needs a value (" + e.value_name + ")");
            value = argv[++i];
        }
        values_[arg] = value;
    }
    if (has("help")) {
        std::cout << usage();
        return false;
    }
    return true;
}

bool cli::has(const std::string& name) const {
    find(name);
    return values_.count(name) != 0;
}

std::string cli::get(const std::string& name) const {
    const entry& e = find(name);
    const auto it = values_.find(name);
    return it != values_.end() ? it->second : e.default_value;
}

int cli::get_int(const std::string& name) const {
    const std::string s = get(name);
    std::size_t used = 0;
    long v = 0;
    try { v = std::stol(s, &used); } catch (const std::exception&) { used = 0; }
    if (used != s.size() || s.empty() || v < -2147483647L || v > 2147483647L)
        throw usage_error(dashed(name) + " expects an integer, got '" + s + "'");
    return int(v);
}

double cli::get_double(const std::string& name) const {
    const std::string s = get(name);
    std::size_t used = 0;
    double v = 0.0;
    try { v = std::stod(s, &used); } catch (const std::exception&) { used = 0; }
    if (used != s.size() || s.empty() || !std::isfinite(v))
        throw usage_error(dashed(name) + " expects a finite number, got '" + s + "'");
    return v;
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

void prepare_output(const std::filesystem::path& file, bool user_named, bool force) {
    namespace fs = std::filesystem;
    if (file.empty()) throw std::runtime_error("empty output path");
    std::error_code ec;
    if (fs::is_directory(file, ec)) throw std::runtime_error("cannot write '" + file.string() + "': it is a folder");
    if (user_named && !force && fs::exists(file, ec))
        throw std::runtime_error("'" + file.string() + "' exists; not overwriting it (pass --force to replace it)");
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    fs::create_directories(folder, ec);
    if (!fs::is_directory(folder))
        throw std::runtime_error("cannot create folder '" + folder.string() + "' for '" + file.string() + "'" +
                                 (ec ? ": " + ec.message() : std::string()));
    if (access(folder.c_str(), W_OK) != 0)
        throw std::runtime_error("cannot write into folder '" + folder.string() + "' (permission denied)");
}

image_size read_image_size(const cli& args, int default_width, int max_side) {
    image_size size;
    size.width = args.has("width") ? args.get_int("width") : default_width;
    size.height = args.has("height") ? args.get_int("height") : size.width * 3 / 4;
    if (size.width < 1 || size.width > max_side || size.height < 1 || size.height > max_side)
        throw usage_error("--width and --height must lie in [1, " + std::to_string(max_side) + "]");
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
    std::ifstream f(file);
    if (!f) throw std::runtime_error("cannot read '" + file.string() + "'");
    std::string line;
    if (!std::getline(f, line) || line != header)
        throw std::runtime_error("'" + file.string() + "' is not " + what + " (its first line should be '" + header +
                                 "')");
    const std::size_t fields = split_fields(header).value().size();
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
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(cell, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != cell.size() || !std::isfinite(v) || v < 0.0)
        throw std::runtime_error(file.string() + ", line " + std::to_string(row.line) + ": '" + cell +
                                 "' is not a number >= 0");
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
