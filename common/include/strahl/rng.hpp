// PCG32 random numbers: M. E. O'Neill, "PCG: A Family of Simple Fast Space-Efficient Statistically Good
// Algorithms for Random Number Generation", 2014 (the XSH-RR variant, 64-bit state, 32-bit output).
// Deterministic for a given (seed, stream): the course's rays and renders reproduce bit for bit.
#pragma once
#include <cstdint>

namespace strahl {

class pcg32 {
public:
    explicit pcg32(std::uint64_t seed = 0x853c49e6748fea9bULL, std::uint64_t stream = 0xda3e39cb94b95bdbULL) {
        inc_ = (stream << 1u) | 1u;
        state_ = 0;
        next_u32();
        state_ += seed;
        next_u32();
    }

    std::uint32_t next_u32() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        const auto rot = std::uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    // Uniform in [0, 1): the top 24 bits, so every value is exactly representable and 1 is never returned.
    float next_float() { return float(next_u32() >> 8) * 0x1p-24f; }

    // Uniform integer in [0, bound) without modulo bias.
    std::uint32_t next_bounded(std::uint32_t bound) {
        const std::uint32_t threshold = (0u - bound) % bound;
        for (;;) {
            const std::uint32_t r = next_u32();
            if (r >= threshold) return r % bound;
        }
    }

private:
    std::uint64_t state_, inc_;
};

}  // namespace strahl
