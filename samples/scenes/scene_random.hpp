// Seeded randomness for scenes. Uniform doubles are built from raw mt19937_64 bits (not
// std::uniform_real_distribution, whose output differs between standard libraries), so a seed
// gives the same trial everywhere.
#pragma once
#include <cstdint>
#include <random>

namespace verve::scenes {

class SceneRandom {
public:
    explicit SceneRandom(std::uint64_t seed) : engine_(seed) {}
    double uniform(double lo, double hi) {
        const double unit = static_cast<double>(engine_() >> 11) * 0x1.0p-53;  // [0, 1)
        return lo + (hi - lo) * unit;
    }

private:
    std::mt19937_64 engine_;
};

}  // namespace verve::scenes
