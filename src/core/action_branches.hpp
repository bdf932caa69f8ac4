// Action branches (docs/algorithm.md, "Action branches"): an NPC that moves, turns and uses at once
// makes one choice per branch on every step, each by an actor head of its own. The heads' neurons
// sit side by side in the actor's columns, branch after branch; one set of actions is one branch.
// The critic and the TD error are shared: a step's error credits every branch's chosen neuron
// through its trace, as ML-Agents' multi-discrete actions share one advantage. A combined action
// index (mixed radix, branch 0 fastest) keeps every interface that passes one action unchanged.
#pragma once
#include <cstdint>

#include "verve/agent_descriptor.hpp"

namespace verve::core {

struct ActionBranches {
    static constexpr std::uint32_t kMax = DescriptorLimits::kMaxActionBranches;
    std::uint32_t count = 1;
    std::uint32_t size[kMax] = {};
    std::uint32_t offset[kMax] = {};  // each branch's first actor column
    std::uint32_t columns = 0;        // actor neurons: the sizes summed

    static ActionBranches single(std::uint32_t numActions);
    static ActionBranches of(const AgentDescriptor& desc);  // desc validated
    // The actor column of each branch's choice within the combined `action`, into out[0..count);
    // returns count.
    std::uint32_t columnsOf(std::uint32_t action, std::uint32_t* out) const {
        for (std::uint32_t b = 0; b < count; ++b) {
            out[b] = offset[b] + action % size[b];
            action /= size[b];
        }
        return count;
    }
};

}  // namespace verve::core
