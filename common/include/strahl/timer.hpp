// Wall-clock timing and the median the course quotes (machines here are shared and noisy).
#pragma once
#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <vector>

namespace strahl {

class timer {
public:
    timer() : start_(clock::now()) {}
    void restart() { start_ = clock::now(); }
    double seconds() const { return std::chrono::duration<double>(clock::now() - start_).count(); }
    double milliseconds() const { return seconds() * 1e3; }

private:
    using clock = std::chrono::steady_clock;
    clock::time_point start_;
};

// Median of the samples (mean of the two middle ones for an even count). Throws on an empty list.
inline double median(std::vector<double> samples) {
    if (samples.empty()) throw std::invalid_argument("median of no samples");
    const std::size_t mid = samples.size() / 2;
    std::nth_element(samples.begin(), samples.begin() + mid, samples.end());
    if (samples.size() % 2) return samples[mid];
    const double upper = samples[mid];
    return 0.5 * (upper + *std::max_element(samples.begin(), samples.begin() + mid));
}

// The median of `repeats` timed runs of f (after one untimed warm-up), in milliseconds.
template <class F>
double median_ms(int repeats, F&& f) {
    f();
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) {
        const timer t;
        f();
        ms.push_back(t.milliseconds());
    }
    return median(ms);
}

}  // namespace strahl
