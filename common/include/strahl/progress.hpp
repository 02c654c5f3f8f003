// A progress bar on standard error for long loops: percentage, rate and ETA. It draws only when standard
// error is a terminal (logs and CI stay clean) and at most ten times a second. Thread-safe: any thread may
// call add().
#pragma once
#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>

namespace strahl {

class progress_bar {
public:
    // total: units of work (e.g. pixel rows); unit: what one unit is called in the rate ("rows").
    progress_bar(std::string label, std::uint64_t total, std::string unit = "items");
    ~progress_bar();  // finishes the line if finish() was not called
    progress_bar(const progress_bar&) = delete;
    progress_bar& operator=(const progress_bar&) = delete;

    void add(std::uint64_t done = 1);
    void finish();

    // Whether this bar draws (standard error is a terminal). Tests can force it off or on.
    bool drawing() const { return draw_; }
    void set_drawing(bool on) { draw_ = on; }
    std::uint64_t done() const { return done_.load(); }

    // The bar's text for `done` of `total` after `seconds`, e.g.
    // "render  [#########           ]  45%  12.3 k rows/s  ETA 3.2 s". Public for tests.
    static std::string format(const std::string& label, std::uint64_t done, std::uint64_t total,
                              double seconds, const std::string& unit, int width = 30);

private:
    void draw(bool final);
    std::string label_, unit_;
    std::uint64_t total_;
    std::atomic<std::uint64_t> done_{0};
    std::atomic<double> last_draw_{-1.0};
    double start_;
    bool draw_;
    bool finished_ = false;
    std::mutex mutex_;
};

}  // namespace strahl
