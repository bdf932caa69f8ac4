// Descriptors of n plain continuous sensors, and the same with an adaptation bit cleared, shared by
// the core tests of lattice layouts (sensor groups, the fine lattice, the pairs beside).
#pragma once
#include <cstddef>
#include <cstdint>

#include "verve/agent_descriptor.hpp"

namespace verve::coretest {

inline AgentDescriptor continuousSensors(std::size_t n) {
    AgentDescriptor d;
    for (std::size_t i = 0; i < n; ++i) d.addContinuousSensor();
    return d;
}

inline AgentDescriptor withoutAdaptation(AgentDescriptor d, std::uint32_t bit) {
    d.adaptation &= ~bit;
    return d;
}

}  // namespace verve::coretest
