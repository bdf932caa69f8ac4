// A value-function picture of a trained agent (thesis figures 19, 23, 36): V sampled over one or
// two sensors with the others held at 0, via Agent::sampleValueFunction.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "verve/agent.hpp"

namespace verve::demo {

struct ValueAxisInfo {
    ValueAxis axis;
    std::string label;
    std::vector<double> coordinates;  // sensor value of each sample
};

struct ValueImage {
    std::vector<ValueAxisInfo> axes;  // 1 or 2; axis 0 varies fastest in `values`
    std::vector<float> values;
};

// Picks the axes: the last two continuous sensors (pendulum: angle x velocity; cart-pole: a
// slice through pole angle x angular velocity at x = x' = 0), else one continuous and the first
// discrete, else the first two discrete sensors (grid x, y). nullopt when the agent has none.
std::optional<ValueImage> sampleValueImage(const Agent& agent, const std::vector<std::string>& sensorNames,
                                           std::uint32_t continuousSamples = 64);

}  // namespace verve::demo
