// What an agent's sensors read on one step.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "verve/agent_descriptor.hpp"

namespace verve {

// A non-owning view: what the C ABI and bindings pass without copying.
struct ObservationView {
    const std::int32_t* discrete = nullptr;
    std::size_t numDiscrete = 0;
    const float* continuous = nullptr;
    std::size_t numContinuous = 0;
};

struct Observation {
    std::vector<std::int32_t> discrete;
    std::vector<float> continuous;

    Observation() = default;
    // Sized for the descriptor, all values zero.
    explicit Observation(const AgentDescriptor& desc)
        : discrete(desc.discreteSensors.size(), 0), continuous(desc.continuousSensors.size(), 0.0f) {}

    void setDiscrete(std::size_t i, std::int32_t value) { discrete.at(i) = value; }
    void setContinuous(std::size_t i, float value) { continuous.at(i) = value; }

    ObservationView view() const {
        return ObservationView{discrete.data(), discrete.size(), continuous.data(), continuous.size()};
    }
};

}  // namespace verve
