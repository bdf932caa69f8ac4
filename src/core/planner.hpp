// Planning (thesis chapter 2 "Efficient Learning from a Few Trials", chapter 4 "Planning"): after a
// real step, an imagined trajectory starts at the current real state, follows the policy through
// the predictive model and trains the critic and actor on the predicted rewards (plus curiosity).
// It ends when the model's uncertainty exceeds the threshold (summed along the plan, as the
// original did, or per step), when the model predicts the end of the trial, or at the step cap,
// so one plan costs at most maxSteps model queries.
//
// With continuous sensors and no curiosity, a plan teaches only if it reaches the end of the trial
// (a dry run first, then the same trajectory learned, so such a plan costs up to twice the
// queries): imagined steps that merely walk the known region back up the per-step reward drag the
// overlapping RBFs of the unvisited states next to it down too, and the optimism that drives plain
// RL toward new states is lost (docs/planning.md). The end counts only if the model is sure of
// that last transition (planner.cpp). The agent caps such plans at one discount time
// constant (tau_discount / dt steps): far from the end, the rollouts that reach it are the policy's
// rare lucky ones, and teaching only those made an agent learn values its policy does not earn
// (docs/planning.md, "Plans look one time constant ahead").
// With discrete features an unvisited state shares nothing with the visited ones, so there every
// plan teaches, as in the thesis: its backups are what push the agent toward the unexplored.
// For the same reason such plans teach the actor only at the real state they start from, and the
// critic all along: imagined actor updates, many per real step and all where plans end, reach
// every overlapping RBF, so the preference a plan taught beside a wall (go up, to the goal) leaks
// to the other side of it, where it leads into a dead end (docs/planning.md, "The actor learns
// where the agent is").
//
// After such a plan has taught, the actor weighs every action at the real state it started from,
// not only the one the plan drew: each allowed action whose one-step prediction the model is sure of
// gets an actor step toward its predicted advantage, at 1/A of the actor's rate (as if each had been
// tried with equal chance). The plans that teach beside an end the model blurs leave the critic a
// little too high there, and an actor that credits only the drawn action took the TD errors that
// follow as preferences (on the continuous 1-D hot plate, more "stay" 4-7 cells from the edge, and
// planning was 0.4% slower than RL alone; docs/planning.md, "After a plan, the actor weighs every
// action the model is sure of"). Actions the model is unsure of are left to exploration.
//
// An imagined step from the real state that stays there (a lever of a one-state task, a wall
// bumped from where the agent stands) is not learned; the plan draws another action from the real
// state instead, within the same cap. The model's guess of that step is the last real outcome of
// the same situation, and replaying it every real step counts one sample many times: on a bandit
// whose levers' payoffs are noisy (and clamped to the reward range, so a good lever's last payoff
// reads as certain) planning agents committed to a lever after a few lucky pulls (docs/experiments.md,
// "Planning on every task"); in a one-state task plans now learn nothing. Ending the plan there
// instead cost the discrete mazes early learning (maze #2, first 10 trials: 222 -> 430 steps; skipping,
// 258). Deeper imagined steps that stay in place still teach: that is where plans learn about
// walls away from the agent. Only plans of discrete, non-curious agents skip such steps: plans that must reach the end of the trial (above)
// learn only from paths that lead somewhere, and a curious agent's bonus is what its plans are for
// (with the skip, the curiosity grid's curious agents lost 1.2 of their reward over 10 seeds).
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
    ValueBounds values;       // TD errors bootstrap only from values within them (td_learner.hpp)
    RewardRange rewards;      // predicted rewards are clamped to the real ones seen
    bool onlyPlansThatEnd = false;  // learn only from plans that reach the end of the trial
    bool actorLearnsAtStartOnly = false;  // imagined states past the first train the critic only
    bool replaysNoStayAtStart = false;    // a first imagined step that stays where it is is not learned
    bool weighsEveryAction = false;       // a plan that ran: the actor weighs every action at its start
    const std::uint8_t* allowed = nullptr;  // the real step's action mask (nullptr: all): what is weighed
    bool predictsChange = true;     // the model's continuous outputs are changes (predictive_model.hpp)
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

    // `start` and `startContinuous`: the real state a plan starts from, its features and its
    // (normalised) continuous values.
    PlanResult run(const PlanSettings& settings, const std::vector<ActiveFeature>& start, const float* startContinuous,
                   WeightTable& w, const StateRepresentation& rep, const PredictiveModel& model, Rng& rng);

private:
    // Whether the plan run() would make reaches a predicted end of the trial (it draws from a copy
    // of the random stream, so the plan that follows takes the same first steps).
    bool reachesTheEnd(const PlanSettings& settings, const std::vector<ActiveFeature>& start,
                       const float* startContinuous, const WeightTable& w, const StateRepresentation& rep,
                       const PredictiveModel& model, Rng rng);
    // The imagined state becomes the real one a plan starts from: its features in phi_, its
    // continuous values in prediction_.continuous (where every prediction then leaves the next's).
    void startAt(const std::vector<ActiveFeature>& start, const float* startContinuous);
    // Predicts the imagined state's successor into prediction_.
    void predict(const PlanSettings& settings, const WeightTable& w, const PredictiveModel& model, std::uint32_t action);
    // At the real state a plan started from: every allowed action whose step the model is sure of
    // gets an actor step toward r + gamma V(s') - V(s), as the model predicts it (r alone at an end).
    void weighEveryAction(const PlanSettings& settings, const std::vector<ActiveFeature>& start,
                          const float* startContinuous, WeightTable& w, const StateRepresentation& rep,
                          const PredictiveModel& model);

    TdLearner td_;
    Prediction prediction_;
    std::vector<ActiveFeature> phi_, next_;  // scratch: the imagined state and its successor
    std::vector<float> activations_;
};

}  // namespace verve::core
