// The opaque handle behind verve_agent*: a verve::Agent and nothing else.
#pragma once
#include <utility>

#include "capi/capi_guard.hpp"
#include "verve/agent.hpp"

struct verve_agent {
    explicit verve_agent(verve::Agent&& a) : agent(std::move(a)) {}
    verve::Agent agent;
};

namespace verve::capi {

inline Agent& agentOf(verve_agent* handle) {
    requireArg(handle, "agent");
    return handle->agent;
}

inline const Agent& agentOf(const verve_agent* handle) {
    requireArg(handle, "agent");
    return handle->agent;
}

// Hands a new agent to the host: *out is written only once everything has succeeded.
inline void handOut(Agent&& agent, verve_agent** out) { *out = new verve_agent(std::move(agent)); }

}  // namespace verve::capi
