#include "core/td_learner.hpp"

#include <algorithm>
#include <cmath>

namespace verve::core {

TdLearner::TdLearner(std::uint32_t numActions, float traceThreshold)
    : numActions_(numActions), stride_(1 + numActions), threshold_(traceThreshold) {}

float TdLearner::value(const WeightTable& w, const std::vector<ActiveFeature>& phi) const {
    float v = 0.0f;
    for (const auto& f : phi) v += w.row(f.index)[WeightLayout::kValue] * f.activation;
    return v;
}

std::uint32_t TdLearner::chooseAction(const WeightTable& w, const std::vector<ActiveFeature>& phi, Rng& rng,
                                      std::vector<float>& activations) const {
    activations.assign(numActions_, 0.0f);
    for (const auto& f : phi) {
        const float* policy = w.row(f.index) + WeightLayout::kPolicy;
        for (std::uint32_t a = 0; a < numActions_; ++a) activations[a] += policy[a] * f.activation;
    }
    float total = 0.0f;
    for (auto& y : activations) {
        y = 1.0f / (1.0f + std::exp(-y));
        total += y;
    }
    if (!(total > 0.0f) || !std::isfinite(total)) return rng.below(numActions_);
    // Roulette (winner-take-all): each action in proportion to its neuron's activation.
    float pick = rng.uniform() * total;
    for (std::uint32_t a = 0; a < numActions_; ++a) {
        pick -= activations[a];
        if (pick < 0.0f) return a;
    }
    // Rounding left a sliver: the last action with any activation takes it.
    for (std::uint32_t a = numActions_; a-- > 0;) {
        if (activations[a] > 0.0f) return a;
    }
    return numActions_ - 1;
}

void TdLearner::train(WeightTable& w, float delta, TdRates rates) const {
    if (delta == 0.0f) return;
    const float dv = rates.value * delta;
    const float dp = rates.policy * delta;
    for (std::size_t slot = 0; slot < features_.size(); ++slot) {
        float* row = w.row(features_[slot]);
        const float* e = traces_.data() + slot * stride_;
        row[WeightLayout::kValue] += dv * e[0];
        for (std::uint32_t a = 0; a < numActions_; ++a) row[WeightLayout::kPolicy + a] += dp * e[1 + a];
    }
}

void TdLearner::decay(float factor) {
    std::size_t kept = 0;
    for (std::size_t slot = 0; slot < features_.size(); ++slot) {
        float* e = traces_.data() + slot * stride_;
        float largest = 0.0f;
        for (std::uint32_t k = 0; k < stride_; ++k) {
            e[k] *= factor;
            largest = std::max(largest, e[k]);
        }
        const std::uint32_t feature = features_[slot];
        if (largest < threshold_) {
            slotOf_[feature] = -1;
            continue;
        }
        if (kept != slot) {  // compact in place, keeping the order (deterministic sums)
            features_[kept] = feature;
            std::copy(e, e + stride_, traces_.data() + kept * stride_);
        }
        slotOf_[feature] = static_cast<std::int32_t>(kept);
        ++kept;
    }
    features_.resize(kept);
    traces_.resize(kept * stride_);
}

std::uint32_t TdLearner::slotFor(std::uint32_t feature) {
    if (slotOf_[feature] >= 0) return static_cast<std::uint32_t>(slotOf_[feature]);
    const auto slot = static_cast<std::uint32_t>(features_.size());
    features_.push_back(feature);
    traces_.resize(traces_.size() + stride_, 0.0f);
    slotOf_[feature] = static_cast<std::int32_t>(slot);
    return slot;
}

void TdLearner::mark(const std::vector<ActiveFeature>& phi, std::uint32_t action, std::uint32_t featureCount) {
    if (slotOf_.size() < featureCount) slotOf_.resize(featureCount, -1);
    for (const auto& f : phi) {
        if (f.activation < threshold_) continue;  // would be dropped at the next decay anyway
        const std::uint32_t slot = slotFor(f.index);  // may grow traces_: take data() after it
        float* e = traces_.data() + std::size_t(slot) * stride_;
        e[0] = std::max(e[0], f.activation);
        e[1 + action] = std::max(e[1 + action], f.activation);
    }
}

void TdLearner::clear() {
    for (auto feature : features_) slotOf_[feature] = -1;
    features_.clear();
    traces_.clear();
}

void TdLearner::restore(const std::vector<std::uint32_t>& features, const std::vector<float>& traces,
                        std::uint32_t featureCount) {
    clear();
    slotOf_.assign(featureCount, -1);
    features_ = features;
    traces_ = traces;
    for (std::size_t slot = 0; slot < features_.size(); ++slot) slotOf_[features_[slot]] = static_cast<std::int32_t>(slot);
}

}  // namespace verve::core
