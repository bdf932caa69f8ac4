#include "core/planner.hpp"

#include <algorithm>
#include <utility>

#include "core/curiosity.hpp"

namespace verve::core {
namespace {

// A plan that must reach the end of the trial trusts only an end whose own transition the model
// is sure of. Where a terminal step sits next to ordinary ones, the model's RBFs blur the two
// together, and its end lands a step early with a reward between them; the model's error estimate
// there is high (0.25-0.3 per step beside the corridor's goal, against ~0 along it). Ends that
// uncertain taught values no policy earns (docs/planning.md, "Only an end the model is sure of is
// trusted": 0.02-0.2 measured, 0.2 kept; 0.3 acts as none).
constexpr float kTrustedEndUncertainty = 0.2f;

bool sameFeatures(const std::vector<ActiveFeature>& a, const std::vector<ActiveFeature>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const ActiveFeature& x, const ActiveFeature& y) {
        return x.index == y.index && x.activation == y.activation;
    });
}

}  // namespace

Planner::Planner(const AgentDescriptor& desc) : td_(ActionBranches::of(desc), 0, desc.traceThreshold) {
    prediction_.discrete.resize(desc.discreteSensors.size());
    prediction_.continuous.resize(desc.continuousSensors.size());
    activations_.reserve(std::size_t(td_.columns()) + 1);  // chooseAction's scratch: the trace stride
}

void Planner::reserve(std::uint32_t features) {
    reserveRoom(phi_, StateRepresentation::foundCapacity(features));
    reserveRoom(next_, StateRepresentation::foundCapacity(features));
    td_.reserve(features, StateRepresentation::foundCapacity(features));
}

void Planner::startAt(const std::vector<ActiveFeature>& start, const float* startContinuous) {
    phi_.assign(start.begin(), start.end());
    std::copy_n(startContinuous, prediction_.continuous.size(), prediction_.continuous.begin());
}

void Planner::predict(const PlanSettings& s, const WeightTable& w, const PredictiveModel& model, std::uint32_t action) {
    // A change model adds to the imagined state's values, which the prediction overwrites in place.
    model.predict(w, phi_, action, s.predictsChange ? prediction_.continuous.data() : nullptr, prediction_);
}

bool Planner::reachesTheEnd(const PlanSettings& s, const std::vector<ActiveFeature>& start,
                            const float* startContinuous, const WeightTable& w, const StateRepresentation& rep,
                            const PredictiveModel& model, Rng rng) {
    startAt(start, startContinuous);
    float uncertainty = 0.0f;
    for (std::uint32_t step = 0; step < s.maxSteps && !phi_.empty(); ++step) {
        float value = 0.0f;
        const std::uint32_t action = td_.chooseAction(w, phi_, rng, activations_, value);
        predict(s, w, model, action);
        uncertainty = s.accumulate ? uncertainty + prediction_.uncertainty : prediction_.uncertainty;
        if (uncertainty > s.uncertaintyThreshold) return false;
        if (prediction_.terminal > 0.5f) return prediction_.uncertainty <= kTrustedEndUncertainty;
        rep.find(prediction_.discrete.data(), prediction_.continuous.data(), next_);
        std::swap(phi_, next_);
    }
    return false;
}

void Planner::weighEveryAction(const PlanSettings& s, const std::vector<ActiveFeature>& start,
                               const float* startContinuous, WeightTable& w, const StateRepresentation& rep,
                               const PredictiveModel& model) {
    const float v = bounded(td_.value(w, start), s.values);
    // Sure: within a trusted end's limit and the plan's own threshold (long plans on continuous maze
    // #2, threshold 0.1, were slower than RL alone with 0.2 alone: docs/planning.md).
    const float sure = std::min(kTrustedEndUncertainty, s.uncertaintyThreshold);
    // Each action as if tried with equal chance: together one real step's worth of actor learning.
    // The critic and the model do not learn here, so every action is judged on the same values.
    const std::uint32_t actions = td_.columns();  // planning has one action set: a column per action
    const TdRates rates{0.0f, s.rates.policy / static_cast<float>(actions), s.rates.policyRange};
    td_.clear();  // the plan's traces; each step below decays by 0, which leaves none live
    for (std::uint32_t a = 0; a < actions; ++a) {
        if (!actionAllowed(s.allowed, a)) continue;
        startAt(start, startContinuous);
        predict(s, w, model, a);
        if (prediction_.uncertainty > sure) continue;  // unknown: left to exploration
        float q = std::clamp(prediction_.reward, s.rewards.anyLow(), s.rewards.anyHigh());
        if (prediction_.terminal <= 0.5f) {
            rep.find(prediction_.discrete.data(), prediction_.continuous.data(), next_);
            if (next_.empty()) continue;
            q += s.gamma * bounded(td_.value(w, next_), s.values);
        }
        td_.mark(start, a, rep.featureCount());
        td_.trainAndDecay(w, q - v, rates, 0.0f);
    }
}

PlanResult Planner::run(const PlanSettings& s, const std::vector<ActiveFeature>& start, const float* startContinuous,
                        WeightTable& w, const StateRepresentation& rep, const PredictiveModel& model, Rng& rng) {
    if (s.onlyPlansThatEnd && !reachesTheEnd(s, start, startContinuous, w, rep, model, rng)) return PlanResult{};
    PlanResult result;
    TdRates rates = s.rates;  // actorLearnsAtStartOnly: the actor rate drops to 0 after the first step
    td_.clear();
    startAt(start, startContinuous);
    float uncertainty = 0.0f;
    for (std::uint32_t query = 0; query < s.maxSteps && !phi_.empty(); ++query) {
        float value = 0.0f;
        const std::uint32_t action = td_.chooseAction(w, phi_, rng, activations_, value);
        predict(s, w, model, action);
        uncertainty = s.accumulate ? uncertainty + prediction_.uncertainty : prediction_.uncertainty;
        const bool trusted = uncertainty <= s.uncertaintyThreshold;
        const bool ends = prediction_.terminal > 0.5f;
        if (trusted && !ends) {
            rep.find(prediction_.discrete.data(), prediction_.continuous.data(), next_);
            if (s.replaysNoStayAtStart && result.steps == 0 && sameFeatures(phi_, next_)) continue;
        }
        const float bonus = curiosityReward(s.curiosity, s.curiosityFactor, prediction_);
        td_.mark(phi_, action, rep.featureCount());
        const float v = bounded(value, s.values);
        if (!trusted) {
            // Too uncertain to trust the predicted successor. A novelty-curious agent still learns
            // that this step leads into the unknown, as a terminal reward: the frontier attracts.
            if (s.curiosity == CuriosityMode::Novelty) {
                td_.trainAndDecay(w, bonus - v, rates, 0.0f);
                result.curiosity += bonus;
                ++result.steps;
            }
            break;
        }
        const float reward = std::clamp(prediction_.reward, s.rewards.anyLow(), s.rewards.anyHigh()) + bonus;
        result.curiosity += bonus;
        ++result.steps;
        if (ends) {  // the trial ends: nothing to bootstrap from
            td_.trainAndDecay(w, reward - v, rates, 0.0f);
            break;
        }
        td_.trainAndDecay(w, reward + s.gamma * bounded(td_.value(w, next_), s.values) - v, rates, s.traceDecay);
        std::swap(phi_, next_);
        if (s.actorLearnsAtStartOnly) rates.policy = 0.0f;
    }
    if (s.weighsEveryAction && result.steps > 0) weighEveryAction(s, start, startContinuous, w, rep, model);
    return result;
}

}  // namespace verve::core
