#include "core/demonstration.hpp"

#include <algorithm>

#include "core/td_learner.hpp"

namespace verve::core {

void imitate(WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action, const ActionBranches& branches,
             const std::uint8_t* allowed, float rate, const PolicyRange& range) {
    std::uint32_t chosen[ActionBranches::kMax];
    branches.columnsOf(action, chosen);
    std::uint32_t branch = 0;  // the branch of column b
    for (std::uint32_t b = 0; b < branches.columns; ++b) {
        while (branch + 1 < branches.count && b >= branches.offset[branch + 1]) ++branch;
        if (!actionAllowed(allowed, b)) continue;
        float x = 0.0f;
        for (const ActiveFeature& f : phi) x += w.row(f.index)[WeightLayout::kPolicy + b] * f.activation;
        // Saturated preferences (|x| beyond ~88) give a step of 0 or +-1: always finite. Held to the
        // limit of a TD step (TdLearner::kStepLimit), so that no policy rate a descriptor allows
        // takes a weight anywhere near AgentSnapshot::kWeightLimit.
        const float target = b == chosen[branch] ? 1.0f : 0.0f;
        const float step = std::clamp(rate * (target - sigmoid(x)), -TdLearner::kStepLimit, TdLearner::kStepLimit);
        for (const ActiveFeature& f : phi) {
            float& weight = w.row(f.index)[WeightLayout::kPolicy + b];
            weight += step * f.activation;
            weight = range.clamp(weight);
        }
    }
}

}  // namespace verve::core
