#include "strahl/progress.hpp"
#include <chrono>
#include <cmath>
#include <cstdio>
#include <unistd.h>

namespace strahl {

namespace {
double now_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string human_rate(double per_second) {
    char buf[32];
    if (per_second >= 1e9) std::snprintf(buf, sizeof buf, "%.1f G", per_second / 1e9);
    else if (per_second >= 1e6) std::snprintf(buf, sizeof buf, "%.1f M", per_second / 1e6);
    else if (per_second >= 1e3) std::snprintf(buf, sizeof buf, "%.1f k", per_second / 1e3);
    else std::snprintf(buf, sizeof buf, "%.1f ", per_second);
    return buf;
}
}  // namespace

progress_bar::progress_bar(std::string label, std::uint64_t total, std::string unit)
    : label_(std::move(label)), unit_(std::move(unit)), total_(total), start_(now_seconds()),
      draw_(isatty(fileno(stderr)) != 0) {}

progress_bar::~progress_bar() { finish(); }

std::string progress_bar::format(const std::string& label, std::uint64_t done, std::uint64_t total,
                                 double seconds, const std::string& unit, int width) {
    const double fraction = total ? std::min(1.0, double(done) / double(total)) : 1.0;
    const int filled = int(std::lround(fraction * width));
    std::string bar = label + "  [" + std::string(filled, '#') + std::string(width - filled, ' ') + "]";
    char tail[96];
    const double rate = seconds > 0.0 ? double(done) / seconds : 0.0;
    if (done >= total)
        std::snprintf(tail, sizeof tail, " %3d%%  %s%s/s  %.1f s", int(fraction * 100.0), human_rate(rate).c_str(),
                      unit.c_str(), seconds);
    else if (rate > 0.0)
        std::snprintf(tail, sizeof tail, " %3d%%  %s%s/s  ETA %.1f s", int(fraction * 100.0),
                      human_rate(rate).c_str(), unit.c_str(), double(total - done) / rate);
    else
        std::snprintf(tail, sizeof tail, " %3d%%", int(fraction * 100.0));
    return bar + tail;
}

void progress_bar::add(std::uint64_t done) {
    done_ += done;
    if (!draw_) return;
    const double t = now_seconds();
    double last = last_draw_.load();
    if (t - last < 0.1) return;
    if (!last_draw_.compare_exchange_strong(last, t)) return;  // another thread draws this time
    draw(false);
}

void progress_bar::finish() {
    std::lock_guard lock(mutex_);
    if (finished_) return;
    finished_ = true;
    if (!draw_) return;
    const std::string line = format(label_, done_.load(), total_, now_seconds() - start_, unit_);
    std::fprintf(stderr, "\r%s\n", line.c_str());
}

void progress_bar::draw(bool) {
    std::lock_guard lock(mutex_);
    if (finished_) return;
    const std::string line = format(label_, done_.load(), total_, now_seconds() - start_, unit_);
    std::fprintf(stderr, "\r%s", line.c_str());
    std::fflush(stderr);
}

}  // namespace strahl
