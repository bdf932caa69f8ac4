// The crowd benchmarks' observation stream (bench/crowd_bench.cpp, verve_update_count's crowd
// shapes): a smooth path through the sensor space, each sensor a sum of two sines.
#pragma once
#include <cmath>
#include <cstdint>

namespace verve::bench {

// Frame t of the path for `sensors` sensors, written to out.
inline void crowdFrame(std::uint32_t sensors, std::uint64_t t, float* out) {
    for (std::uint32_t k = 0; k < sensors; ++k) {
        const float x = 0.011f * static_cast<float>(t);
        out[k] = 0.6f * std::sin(x * (1.0f + 0.37f * static_cast<float>(k)) + static_cast<float>(k)) +
                 0.3f * std::sin(x * (3.1f + 0.53f * static_cast<float>(k)));
    }
}

}  // namespace verve::bench
