// TD(lambda) actor-critic on linear networks (thesis chapter 4, "Temporal Difference Learning").
//
// Critic: V(s) = sum_i w_i phi_i. Actor: one sigmoid neuron per action, y_a = 1 / (1 + e^-(sum_i w_ai phi_i)),
// chosen by roulette in proportion to y_a. Both learn w += eta * delta * e. Traces are replacing
// (e = max(e, phi); the actor's only for the chosen action), decay by gamma * lambda and are kept in a
// sparse live list, dropped below a threshold, so work follows live traces, not the feature count.
#pragma once
#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "core/state_representation.hpp"
#include "core/weight_table.hpp"

namespace verve::core {

struct TdRates {
    float value = 0.0f;   // eta_value
    float policy = 0.0f;  // eta_policy = k * eta_value
};

class TdLearner {
public:
    TdLearner(std::uint32_t numActions, float traceThreshold);

    float value(const WeightTable& w, const std::vector<ActiveFeature>& phi) const;
    // Sigmoid action activations y_a into probabilities (unnormalised) and a roulette choice.
    std::uint32_t chooseAction(const WeightTable& w, const std::vector<ActiveFeature>& phi, Rng& rng,
                               std::vector<float>& activations) const;

    // w += eta * delta * e over the live traces.
    void train(WeightTable& w, float delta, TdRates rates) const;
    // e *= factor; traces whose every component falls below the threshold are dropped.
    void decay(float factor);
    // e = max(e, phi) for the critic; e_a = max(e_a, phi) for the chosen action's neuron.
    void mark(const std::vector<ActiveFeature>& phi, std::uint32_t action, std::uint32_t featureCount);
    void clear();

    std::uint32_t liveCount() const { return static_cast<std::uint32_t>(features_.size()); }
    std::uint32_t traceStride() const { return stride_; }
    const std::vector<std::uint32_t>& liveFeatures() const { return features_; }
    const std::vector<float>& liveTraces() const { return traces_; }
    // Restores saved traces (validated by the caller).
    void restore(const std::vector<std::uint32_t>& features, const std::vector<float>& traces,
                 std::uint32_t featureCount);

private:
    std::uint32_t slotFor(std::uint32_t feature);

    std::uint32_t numActions_;
    std::uint32_t stride_;  // 1 + numActions: value trace, then one per action
    float threshold_;
    std::vector<std::uint32_t> features_;  // live trace -> feature
    std::vector<float> traces_;            // live trace -> stride_ values
    std::vector<std::int32_t> slotOf_;     // feature -> live trace slot, or -1
};

}  // namespace verve::core
