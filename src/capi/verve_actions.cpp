// Action branches: the choices within a combined action and back (core/action_branches.hpp).
#include <string>

#include "capi/capi_agent.hpp"

using verve::capi::AgentUse;
using verve::capi::guarded;
using verve::capi::requireArg;

namespace {

std::uint32_t branchCount(const verve::AgentDescriptor& d) {
    return d.actionBranches.empty() ? 1u : static_cast<std::uint32_t>(d.actionBranches.size());
}

}  // namespace

extern "C" {

VERVE_API verve_result VERVE_CALL verve_agent_split_action(const verve_agent* agent, uint32_t action, uint32_t* out_choices,
                                                           uint32_t n_branches) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::AgentDescriptor& d = use.agent().descriptor();
        requireArg(out_choices, "out_choices");
        if (n_branches != branchCount(d)) {
            throw verve::Error(verve::ErrorCode::InvalidArgument, "n_branches is " + std::to_string(n_branches) +
                                                                      ", the agent has " + std::to_string(branchCount(d)));
        }
        if (action >= d.numActions) {
            throw verve::Error(verve::ErrorCode::InvalidArgument, "action " + std::to_string(action) +
                                                                      " is out of range (the agent has " +
                                                                      std::to_string(d.numActions) + " combined actions)");
        }
        for (uint32_t b = 0; b < n_branches; ++b) out_choices[b] = d.branchChoice(action, b);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_join_action(const verve_agent* agent, const uint32_t* choices,
                                                          uint32_t n_branches, uint32_t* out_action) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        requireArg(choices, "choices");
        requireArg(out_action, "out_action");
        *out_action = use.agent().descriptor().actionOf(choices, n_branches);
    });
}

}  // extern "C"
