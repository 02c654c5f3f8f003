// STRAHL_TODO: the body of every exercise stub. It throws strahl::not_implemented carrying the exercise id,
// the file and the line, so a program can say exactly which exercise is missing, e.g.
//   exercise 01.2 (ray/sphere) is not done yet: exercises/01_first_tracer/sphere.cpp:21
#pragma once
#include <stdexcept>
#include <string>

namespace strahl {

class not_implemented : public std::logic_error {
public:
    // id is "NN.K name", e.g. "01.2 ray/sphere".
    not_implemented(std::string id, const char* file, int line)
        : std::logic_error(message(id, file, line)), id_(std::move(id)), file_(file), line_(line) {}

    const std::string& id() const { return id_; }
    const std::string& file() const { return file_; }
    int line() const { return line_; }

private:
    static std::string message(const std::string& id, const char* file, int line) {
        const auto space = id.find(' ');
        const std::string number = id.substr(0, space);
        const std::string name = space == std::string::npos ? std::string() : " (" + id.substr(space + 1) + ")";
        return "exercise " + number + name + " is not done yet: " + file + ":" + std::to_string(line);
    }
    std::string id_, file_;
    int line_;
};

}  // namespace strahl

namespace strahl {
// Throws not_implemented(id, file, line). Out of line (common/src/todo.cpp): a stub inlined into a chapter's
// walk then costs a call, not the exception's string building at every inlined site (which doubled the
// stubs' code and compile time).
[[noreturn]] void todo(const char* id, const char* file, int line);
}  // namespace strahl

#define STRAHL_TODO(id) ::strahl::todo((id), __FILE__, __LINE__)
