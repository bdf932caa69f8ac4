// Consistency checks of an AgentSnapshot against its own descriptor: everything io can verify
// without knowing the algorithm (sizes, ranges, finite numbers). The core checks the rest
// (e.g. the weight stride) when it rebuilds the agent.
#pragma once
#include "verve/agent_snapshot.hpp"

namespace verve::io {

// Throws Error(Format) naming the first inconsistent field.
void checkSnapshot(const AgentSnapshot& snapshot);

// The grouping of a save made before sensor groups: one lattice over all continuous sensors, which
// Auto still is up to 4 of them.
SensorGrouping legacyGrouping(const AgentDescriptor& d);

}  // namespace verve::io
