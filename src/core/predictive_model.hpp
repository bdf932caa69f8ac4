// The predictive model (thesis chapter 2 "Efficient Learning from a Few Trials", chapter 4
// "Predictive Model"): linear networks over the agent's own RBF features that predict, for a
// state and an action, the next observation, the next reward, whether the trial ends, and the
// model's own uncertainty (the expected squared error of those predictions).
//
// The weights live in the agent's WeightTable rows after the critic and actor: per feature, one
// block of outputs per action, so one active feature is still one cache walk. A block holds
//   [continuous next values | discrete outputs | reward | terminal | certainty | fast | slow]
// where discrete outputs are one per value of each discrete sensor (categorical) or one scalar
// per sensor (ordinal, the original's choice). Certainties are stored as 1 - uncertainty so that
// new, all-zero weights mean "fully uncertain": an unexplored state stops a plan.
// Continuous outputs predict how far each value moves (train() says why), not where it lands.
// Fast and slow are two running averages of the same error (learning progress = slow - fast).
#pragma once
#include <cstdint>
#include <vector>

#include "core/state_representation.hpp"
#include "core/weight_table.hpp"
#include "verve/agent_descriptor.hpp"

namespace verve::core {

struct Prediction {
    std::vector<std::int32_t> discrete;
    std::vector<float> continuous;  // in [-1, 1] (wrapped on circular sensors)
    float reward = 0.0f;            // clamped to [-1, 1]
    float terminal = 0.0f;          // in [0, 1]: the trial ends on this transition
    float uncertainty = 1.0f;       // in [0, 1]: expected normalised squared error
    float progress = 0.0f;          // in [-1, 1]: how fast that error has been falling
};

class PredictiveModel {
public:
    explicit PredictiveModel(const AgentDescriptor& desc);

    // Outputs per action block, in 64 bits: validation bounds it before anything is allocated.
    static std::uint64_t outputsPerAction(const AgentDescriptor& desc);
    // Weight columns the model needs per feature (0 when planning is off); desc is validated.
    static std::uint32_t columnsFor(const AgentDescriptor& desc);

    // Delta-rule rate eta_pred = (1 - e^(-dt/tau_pred)) / sum (tau 0: 1 / sum).
    float rate(float dt) const;

    // `from`: the state's continuous values, when the model predicts changes (below); else nullptr.
    // It may be out.continuous itself: each value is read before it is overwritten.
    void predict(const WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action,
                 const float* from, Prediction& out) const;

    // One real transition (phi, action) -> (observation, reward): trains every output and returns
    // the normalised squared error of the prediction made before training, in [0, 1].
    // With `from` (the continuous values the transition started at) the continuous outputs learn
    // the change, next - from; with nullptr the next values themselves (saves from before the change).
    // A change is the same step all over an open space and jumps only at walls, which the RBFs
    // fit; a position is a ramp they only approximate, and plans through blurred positions slip
    // through walls (docs/planning.md, "Predicting changes").
    float train(WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action,
                const float* from, const std::int32_t* discrete, const float* continuous, float reward, float rate);
    // A terminal transition: no next observation, so only reward, terminal and the error
    // estimates learn.
    float trainTerminal(WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action,
                        float reward, float rate);

    // The uncertainty the model predicted for the transition it was last trained on.
    float lastUncertainty() const { return lastUncertainty_; }

private:
    void rawOutputs(const WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action) const;
    float fillTargets(const float* from, const std::int32_t* discrete, const float* continuous, float reward, bool terminal);
    void applyDeltaRule(WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action, float rate);

    std::vector<std::uint32_t> discreteCounts_;
    std::vector<bool> circular_;
    bool categorical_;
    float tau_;
    float activationSum_;
    float invSigma2_;  // 1 / sigma^2: continuous errors are measured in RBF widths
    float lastUncertainty_ = 1.0f;
    std::uint32_t base_;  // first model column of a row

    // Offsets inside an action block.
    std::uint32_t numContinuous_, discreteOutputs_, reward_, terminal_, certainty_, fast_, slow_, block_;

    // Scratch reused on every call (no allocation once built).
    mutable std::vector<float> outputs_;  // raw outputs of one block
    std::vector<float> targets_;
    std::vector<std::uint8_t> trained_;  // which outputs this transition teaches
};

}  // namespace verve::core
