// Learning from a teacher's continuous actions (docs/teaching.md), as core/demonstration.hpp learns
// from a demonstrated discrete action. Each dimension's value v in [-1, 1] is taken back through the
// squash, u = atanh(v) (v held just inside +-1 first: atanh(+-1) is infinite), and then:
// - u takes the place of the agent's own draw in the actor's trace: the mean's and the spread's
//   columns gather the natural gradient of log N(u; x, sigma) at u, as continuous_actions.cpp
//   computes it for a value the agent drew (same clips, same kStepScale), so that the TD errors
//   that follow credit the teacher's choice;
// - the actor takes one step of imitation along that same gradient at the actor's rate (the
//   discrete imitation's cross-entropy gradient is the log-likelihood's for a sigmoid neuron): the
//   mean moves towards u, the spread towards the teacher's distance from the mean.
#pragma once
#include <cstdint>
#include <vector>

#include "core/active_feature.hpp"
#include "core/weight_table.hpp"

namespace verve::core {

// The mean and spread columns' gradients (x_0, y_0, x_1, y_1, ...) of log N(atanh(v_d); x_d, sigma_d)
// for the state's column sums `sums` (as ContinuousActions::act reads them) and the teacher's values.
void demonstratedGradients(const float* sums, const float* values, std::uint32_t count, float* gradients);

// One imitation step: each continuous column c (from `firstColumn` of the actor's) moves by
// rate * gradients[c] * phi_i at feature i, kept within +-ContinuousPolicy::kWeightBound.
void imitateContinuous(WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t firstColumn,
                       std::uint32_t columns, const float* gradients, float rate);

}  // namespace verve::core
