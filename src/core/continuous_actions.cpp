#include "core/continuous_actions.hpp"

#include <algorithm>
#include <cmath>

#include "core/continuous_demonstration.hpp"
#include "core/td_learner.hpp"

namespace verve::core {

float ContinuousPolicy::spread(float y) { return kSpreadLow + (kSpreadHigh - kSpreadLow) * sigmoid(y); }

float normalDraw(Rng& rng) {
    // 1 - uniform() is in (0, 1]: the logarithm stays finite.
    const float radius = std::sqrt(-2.0f * std::log(1.0f - rng.uniform()));
    return radius * std::cos(6.28318530718f * rng.uniform());
}

ContinuousActions::ContinuousActions(std::uint32_t count)
    : count_(count), values_(count, 0.0f), noise_(count, 0.0f), gradients_(2 * std::size_t(count), 0.0f) {}

void ContinuousActions::act(const float* sums, Rng& rng, float dt, bool greedy) {
    // An Ornstein-Uhlenbeck step of unit variance: rho of the old noise, sqrt(1 - rho^2) of a new draw.
    const float rho = running_ ? std::exp(-dt / ContinuousPolicy::kNoiseSeconds) : 0.0f;
    const float fresh = std::sqrt(1.0f - rho * rho);
    for (std::uint32_t d = 0; d < count_; ++d) {
        const float x = sums[2 * d], y = sums[2 * d + 1];
        float* g = gradients_.data() + 2 * d;
        if (greedy) {
            values_[d] = std::tanh(x);
            g[0] = g[1] = 0.0f;
            continue;
        }
        // Clamped: a long run of large draws cannot take it beyond any single draw (saves check it).
        const float n = std::clamp(rho * noise_[d] + fresh * normalDraw(rng), -ContinuousPolicy::kNoiseLimit,
                                   ContinuousPolicy::kNoiseLimit);
        noise_[d] = n;
        const float sigma = ContinuousPolicy::spread(y);
        values_[d] = std::tanh(x + sigma * n);
        // The natural gradient of log N(u; x, sigma) for x is u - x; for log sigma it is (n^2 - 1) / 2,
        // through sigma's sigmoid for y. Clipped: one rare draw must not make a trace on its own.
        const float s = sigmoid(y);
        const float dLogSigma = (ContinuousPolicy::kSpreadHigh - ContinuousPolicy::kSpreadLow) * s * (1.0f - s) / sigma;
        g[0] = ContinuousPolicy::kStepScale * std::clamp(sigma * n, -2.0f, 2.0f);
        g[1] = ContinuousPolicy::kStepScale * std::clamp(0.5f * (n * n - 1.0f), -0.5f, 1.5f) * dLogSigma;
    }
    running_ = !greedy || running_;
}

void ContinuousActions::play(const float* sums, const float* demonstrated) {
    demonstratedGradients(sums, demonstrated, count_, gradients_.data());
    values_.assign(demonstrated, demonstrated + count_);
}

void ContinuousActions::resetNoise() { running_ = false; }

void ContinuousActions::restore(const std::vector<float>& noise, bool running, const std::vector<float>& values) {
    noise_ = noise;
    running_ = running;
    values_ = values;
}

}  // namespace verve::core
