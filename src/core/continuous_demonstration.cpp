#include "core/continuous_demonstration.hpp"

#include <algorithm>
#include <cmath>

#include "core/continuous_actions.hpp"
#include "core/td_learner.hpp"

namespace verve::core {
namespace {

// tanh(u) is 1 in float from u ~ 9; 1 - 2^-20 gives u ~ 7.6, a value the squash can still tell
// from its neighbours and the clips below hold anyway.
constexpr float kEdge = 1.0f - 1.0f / 1048576.0f;

}  // namespace

void demonstratedGradients(const float* sums, const float* values, std::uint32_t count, float* gradients) {
    for (std::uint32_t d = 0; d < count; ++d) {
        const float x = sums[2 * d], y = sums[2 * d + 1];
        const float u = std::atanh(std::clamp(values[d], -kEdge, kEdge));
        const float sigma = ContinuousPolicy::spread(y);
        const float n = (u - x) / sigma;  // the draw that would have played it
        // As ContinuousActions::act for a draw n of its own.
        const float s = sigmoid(y);
        const float dLogSigma = (ContinuousPolicy::kSpreadHigh - ContinuousPolicy::kSpreadLow) * s * (1.0f - s) / sigma;
        gradients[2 * d] = ContinuousPolicy::kStepScale * std::clamp(u - x, -2.0f, 2.0f);
        gradients[2 * d + 1] = ContinuousPolicy::kStepScale * std::clamp(0.5f * (n * n - 1.0f), -0.5f, 1.5f) * dLogSigma;
    }
}

void imitateContinuous(WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t firstColumn,
                       std::uint32_t columns, const float* gradients, float rate) {
    for (std::uint32_t c = 0; c < columns; ++c) {
        // Held to a TD step's limit (TdLearner::kStepLimit), as the discrete imitation.
        const float step = std::clamp(rate * gradients[c], -TdLearner::kStepLimit, TdLearner::kStepLimit);
        for (const ActiveFeature& f : phi) {
            float& weight = w.row(f.index)[WeightLayout::kPolicy + firstColumn + c];
            weight = std::clamp(weight + step * f.activation, -ContinuousPolicy::kWeightBound, ContinuousPolicy::kWeightBound);
        }
    }
}

}  // namespace verve::core
