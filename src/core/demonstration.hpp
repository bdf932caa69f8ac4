// Learning from a demonstrated step (docs/teaching.md): the host says which action was taken (a
// player or the game's scripted AI drove the NPC), and the agent learns from it as follows.
// - The critic learns the step as usual: it values what the demonstrator does, which is what the
//   agent is being shown and what it will start from when it acts on its own.
// - The demonstrated action takes the place of the agent's own choice in the actor's trace, so
//   the TD errors that follow credit it (or blame it) as they would an action the agent chose.
// - The actor is also pulled towards it: one step of imitation on the actor's neurons, each
//   allowed action's sigmoid towards 1 for the demonstrated action and 0 for the others (the
//   gradient of their cross-entropy), at the actor's rate. Credit through TD errors alone is
//   slow when the rewards are sparse; imitation makes the demonstrated policy the agent's own
//   within a few demonstrations, and TD learning then improves on it once the agent acts alone.
// Off-policy: the actor's TD step assumes the action came from its own policy. For a teacher who
// mostly does what the agent would come to do, the bias is small; a teacher who does worse than
// the agent is corrected by the TD errors as soon as the demonstrations stop.
#pragma once
#include <cstdint>
#include <vector>

#include "core/action_branches.hpp"
#include "core/active_feature.hpp"
#include "core/habit_bound.hpp"
#include "core/weight_table.hpp"

namespace verve::core {

// One imitation step at the features `phi` towards `action`: each allowed action's preference
// x_b moves by rate * (t_b - sigmoid(x_b)) * phi_i at feature i (t_b: 1 for `action`, else 0),
// kept within `range`; with branches, each branch's neurons towards its choice within the combined
// `action`. `allowed`: one flag per actor column, or nullptr for all.
void imitate(WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action, const ActionBranches& branches,
             const std::uint8_t* allowed, float rate, const PolicyRange& range);

}  // namespace verve::core
