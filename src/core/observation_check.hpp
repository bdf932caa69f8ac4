// Input validation, done before anything changes so a refused call leaves the agent untouched.
#pragma once
#include <cstdint>
#include <vector>

#include "verve/agent_descriptor.hpp"
#include "verve/observation.hpp"

namespace verve::core {

// Throws Error(InvalidArgument) naming the first bad value. On success writes the continuous
// values clamped to [-1, 1] (wrapped into [-1, 1) when circular) to `normalized`.
void checkObservation(const AgentDescriptor& desc, ObservationView obs, std::vector<float>& normalized);
void checkFinite(float value, const char* what);
void checkTimeStep(float dt);

}  // namespace verve::core
