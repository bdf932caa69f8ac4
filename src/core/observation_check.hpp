// Input validation, done before anything changes so a refused call leaves the agent untouched.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "verve/agent_descriptor.hpp"
#include "verve/observation.hpp"

namespace verve::core {

// Throws Error(InvalidArgument) naming the first bad value. On success writes the continuous
// values clamped to [-1, 1] (wrapped into [-1, 1) where circular[i] is 1) to `normalized`.
// `circular` is StateRepresentation::circular(), which the update reads anyway: the descriptor's
// sensor list would be one more cache miss per update of a crowd's agent.
void checkObservation(const AgentDescriptor& desc, const std::uint8_t* circular, ObservationView obs,
                      std::vector<float>& normalized);
void checkFinite(float value, const char* what);
void checkTimeStep(float dt);
// An action mask: numActions flags, each 0 or 1, at least one 1.
void checkActionMask(const AgentDescriptor& desc, const std::uint8_t* allowed, std::size_t count);

}  // namespace verve::core
