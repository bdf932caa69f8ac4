#include "core/action_branches.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "verve/error.hpp"

namespace verve {

namespace core {

ActionBranches ActionBranches::single(std::uint32_t numActions) {
    ActionBranches b;
    b.size[0] = numActions;
    b.columns = numActions;
    return b;
}

ActionBranches ActionBranches::of(const AgentDescriptor& desc) {
    if (desc.actionBranches.empty()) return single(desc.numActions);
    ActionBranches b;
    b.count = static_cast<std::uint32_t>(desc.actionBranches.size());
    for (std::uint32_t i = 0; i < b.count; ++i) {
        b.size[i] = desc.actionBranches[i];
        b.offset[i] = b.columns;
        b.columns += b.size[i];
    }
    return b;
}

}  // namespace core

AgentDescriptor& AgentDescriptor::setActionBranches(std::vector<std::uint32_t> sizes) {
    if (sizes.empty()) {  // one action set again: numActions stays the user's
        actionBranches.clear();
        return *this;
    }
    // Saturating: a product past the limit stays past it, for validate() to name.
    std::uint64_t product = 1;
    for (std::uint32_t n : sizes) product = std::min<std::uint64_t>(product * n, std::uint64_t(UINT32_MAX));
    actionBranches = std::move(sizes);
    numActions = static_cast<std::uint32_t>(product);
    return *this;
}

std::uint32_t AgentDescriptor::actionChoices() const {
    if (actionBranches.empty()) return numActions;
    std::uint64_t sum = 0;
    for (std::uint32_t n : actionBranches) sum += n;
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(sum, UINT32_MAX));
}

std::uint32_t AgentDescriptor::branchChoice(std::uint32_t action, std::size_t branch) const {
    if (actionBranches.empty()) return branch == 0 ? action : 0;
    for (std::size_t i = 0; i < branch && i < actionBranches.size(); ++i) action /= std::max(1u, actionBranches[i]);
    return branch < actionBranches.size() ? action % std::max(1u, actionBranches[branch]) : 0;
}

std::uint32_t AgentDescriptor::actionOf(const std::uint32_t* choices, std::size_t count) const {
    const std::size_t branches = actionBranches.empty() ? 1 : actionBranches.size();
    if (choices == nullptr || count != branches) {
        throw Error(ErrorCode::InvalidArgument, "an action needs " + std::to_string(branches) + " choice(s), one per branch, got " +
                                                    (choices == nullptr ? std::string("NULL") : std::to_string(count)));
    }
    std::uint64_t action = 0, scale = 1;
    for (std::size_t b = 0; b < branches; ++b) {
        const std::uint32_t n = actionBranches.empty() ? numActions : actionBranches[b];
        if (choices[b] >= n) {
            throw Error(ErrorCode::InvalidArgument, "choice " + std::to_string(choices[b]) + " of branch " + std::to_string(b) +
                                                        " is out of range (the branch has " + std::to_string(n) + " choices)");
        }
        action += scale * choices[b];
        scale *= n;
    }
    return static_cast<std::uint32_t>(action);
}

}  // namespace verve
