// A small seeded generator for tasks. Hand-written (not <random> distributions) so the same seed
// gives the same trials with every standard library.
#pragma once
#include <cmath>
#include <cstdint>

namespace verve::tasks {

// SplitMix64 finaliser: turns (seed, index) pairs into well-mixed, independent seeds.
inline std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t index) {
    std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (index + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

class TaskRng {
public:
    explicit TaskRng(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        state_ += 0x9E3779B97F4A7C15ull;
        return mixSeed(state_, 0);
    }
    // Uniform in [0, n); n > 0. The modulo bias is below 2^-50 for task-sized n.
    std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>(next() % n); }
    // Uniform in [0, 1).
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    // Standard normal (Box-Muller).
    double normal() {
        const double u1 = 1.0 - uniform();  // (0, 1]: log is finite
        const double u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
    }

private:
    std::uint64_t state_;
};

}  // namespace verve::tasks
