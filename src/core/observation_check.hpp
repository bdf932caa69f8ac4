// Input validation, done before anything changes so a refused call leaves the agent untouched.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "verve/agent_descriptor.hpp"
#include "verve/observation.hpp"

namespace verve::core {

// Throws Error(InvalidArgument) naming the first bad value. Reads the descriptor's sensor counts
// only: a batch checks every agent before it updates any, one more trip through a crowd's memory.
void checkObservation(const AgentDescriptor& desc, ObservationView obs);
// A checked observation's continuous values clamped to [-1, 1] (wrapped into [-1, 1) where
// circular[i] is 1). `circular` is StateRepresentation::circular(), which an update reads anyway:
// the descriptor's sensor list would be one more cache miss per update of a crowd's agent.
void normalizeObservation(const std::uint8_t* circular, ObservationView obs, std::vector<float>& normalized);
void checkFinite(float value, const char* what);
void checkTimeStep(float dt);
// An action mask: actionChoices() flags (numActions, or one per choice of each branch), each 0 or 1,
// at least one 1 in each branch.
void checkActionMask(const AgentDescriptor& desc, const std::uint8_t* allowed, std::size_t count);
// A demonstrated action: one of the agent's, and one `allowed` (a checked mask, or nullptr) allows.
void checkDemonstratedAction(const AgentDescriptor& desc, std::uint32_t action, const std::uint8_t* allowed);
// A teacher's continuous actions: `count` values (the agent's continuousActions), each in [-1, 1].
void checkDemonstratedContinuous(const AgentDescriptor& desc, const float* values, std::uint32_t count);

}  // namespace verve::core
