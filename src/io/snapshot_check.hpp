// Consistency checks of an AgentSnapshot against its own descriptor: everything io can verify
// without knowing the algorithm (sizes, ranges, finite numbers). The core checks the rest
// (e.g. the weight stride) when it rebuilds the agent.
#pragma once
#include "verve/agent_snapshot.hpp"

namespace verve::io {

// Throws Error(Format) naming the first inconsistent field.
void checkSnapshot(const AgentSnapshot& snapshot);

}  // namespace verve::io
