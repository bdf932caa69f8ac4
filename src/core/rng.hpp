// A seeded, portable generator (xoshiro256**): one stream per agent, the same bits on every
// platform, and a state small enough to save with the agent.
#pragma once
#include <array>
#include <cstdint>

namespace verve::core {

// The seed of stream `stream` of a family seeded with `seed` (e.g. the bodies of one brain):
// distinct, well-mixed streams, the same on every platform.
std::uint64_t streamSeed(std::uint64_t seed, std::uint64_t stream);

class Rng {
public:
    explicit Rng(std::uint64_t seed = 1);

    std::uint64_t next();
    float uniform();  // [0, 1), 24 random bits
    std::uint32_t below(std::uint32_t n);  // [0, n), n > 0

    const std::array<std::uint64_t, 4>& state() const { return s_; }
    void setState(const std::array<std::uint64_t, 4>& s) { s_ = s; }

private:
    std::array<std::uint64_t, 4> s_{};
};

}  // namespace verve::core
