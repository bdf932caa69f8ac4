// Planning (thesis chapter 2 "Efficient Learning from a Few Trials", chapter 4 "Planning"): after a
// real step, an imagined trajectory starts at the current real state, follows the policy through
// the predictive model and trains the critic and actor on the predicted rewards (plus curiosity).
// It ends when the model's uncertainty exceeds the threshold (summed along the plan, as the
// original did, or per step), when the model predicts the end of the trial, or at the step cap,
// so one plan costs at most maxSteps model queries.
//
// The plan keeps its own eligibility traces, cleared at each plan start: an imagined trajectory
// must not leak into the real one's credit assignment, and vice versa. Imagined states never
// allocate RBFs (StateRepresentation::find).
#pragma once
#include <cstdint>
#include <vector>

#include "core/predictive_model.hpp"
#include "core/rng.hpp"
#include "core/state_representation.hpp"
#include "core/td_learner.hpp"
#include "core/weight_table.hpp"
#include "verve/agent_descriptor.hpp"

namespace verve::core {

struct PlanSettings {
    std::uint32_t maxSteps = 0;
    float uncertaintyThreshold = 0.0f;
    bool accumulate = true;
    CuriosityMode curiosity = CuriosityMode::None;
    float curiosityFactor = 0.0f;
    float gamma = 0.0f;
    float traceDecay = 0.0f;
    TdRates rates;
    float valueBound = 0.0f;  // TD errors bootstrap only from values within it (td_learner.hpp)
};

struct PlanResult {
    std::uint32_t steps = 0;  // imagined transitions learned from
    float curiosity = 0.0f;   // curiosity reward summed over them
};

class Planner {
public:
    explicit Planner(const AgentDescriptor& desc);

    // Room for plans over `features` features: run() then allocates nothing.
    void reserve(std::uint32_t features);

    PlanResult run(const PlanSettings& settings, const std::vector<ActiveFeature>& start, WeightTable& w,
                   const StateRepresentation& rep, const PredictiveModel& model, Rng& rng);

private:
    TdLearner td_;
    Prediction prediction_;
    std::vector<ActiveFeature> phi_, next_;  // scratch: the imagined state and its successor
    std::vector<float> activations_;
};

}  // namespace verve::core
