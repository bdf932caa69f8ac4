// The agent's internals, shared by the files that implement verve::Agent
// (agent.cpp: stepping; agent_snapshot.cpp: snapshot and restore; value_sampling.cpp; brain.cpp).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "core/brain_state.hpp"
#include "core/continuous_actions.hpp"
#include "core/reward_stretch.hpp"

#include "core/planner.hpp"
#include "core/predictive_model.hpp"
#include "core/rng.hpp"
#include "core/state_representation.hpp"
#include "core/td_learner.hpp"
#include "core/teacher.hpp"
#include "core/weight_table.hpp"
#include "verve/agent.hpp"

namespace verve {

// Per-step constants from dt and the time constants (thesis chapter 4).
struct StepConstants {
    float gamma = 0.0f;        // e^(-dt / tau_discount)
    float traceDecay = 0.0f;   // gamma * lambda, lambda = e^(-dt / tau_eligibility)
    core::TdRates rates;       // (1 - e^(-dt / tau_value)) / sum, times k for the policy
    core::ValueBounds values;  // what a policy can earn: TD errors bootstrap only from values within it
};

struct Agent::Impl {
    explicit Impl(const AgentDescriptor& desc);  // with a brain of its own
    // A body of a shared brain: its own short-term memory and random stream `seed`.
    Impl(std::shared_ptr<BrainState> shared, std::uint64_t seed);

    // Agent::update and Agent::updateDemonstrated (`demonstrated`: the action the host took;
    // `demonstratedContinuous`: its continuous actions' values, checked already, or nullptr).
    std::uint32_t step(float reward, ObservationView obs, float dt, ActionMask mask, const std::uint32_t* demonstrated,
                       const float* demonstratedContinuous);
    StepConstants constantsFor(float dt) const;
    StepConstants constantsFor(float dt, const core::RewardRange& rewards) const;  // with these rewards seen
    // tau_discount, or the horizon the trials set with Adaptation::Horizon (core/horizon.hpp).
    float tauDiscount(float dt) const;
    // A real step's TD error trains the critic and actor (traces then decay by `decay`); the
    // error's size informs Adaptation::ActorScale (core/td_scale.hpp).
    void learnReal(float delta, const StepConstants& k, float decay);
    // mark() of this step's features: with Adaptation::GroupRates, each activation times its
    // lattice's scale (core/group_rates.hpp).
    void markStep(std::uint32_t action, const float* gradients);
    // The TD error of the real step that ends in `current` with (clamped) reward r.
    float realTdError(float r, const StepConstants& k) const;
    // Where a state counts as hopeless for this step's choice (core::hopelessValue), and what the
    // choice leaves in the stats and probabilities.
    float hopelessFor(bool samples, const StepConstants& k) const;
    void recordChoice(const std::uint8_t* allowed, float hopeless, const StepConstants& k);
    // The continuous actions' values from the sums chooseAction left after the discrete ones (then
    // dropped from `probabilities`); `greedy`: their means; `demonstrated`: a teacher's values. Their
    // gradients for mark(), or nullptr.
    const float* actContinuous(bool greedy, float dt, const float* demonstrated);
    // The step's end: the teacher's memory (with the continuous `gradients`), `current` becomes
    // `previous`, the stats.
    void endStep(ObservationView obs, float dt, std::uint32_t action, const float* gradients);
    // A trial ends (endEpisode, truncateEpisode): its longest stretch of an unchanged step reward
    // informs the horizon.
    void endTrial();
    void resetShortTermMemory();
    // Planning mode (desc.planning): the model learns the previous real transition, and after a
    // real step an imagined trajectory trains the critic and actor.
    void learnModel(float reward, const std::int32_t* discrete, float dt);
    void learnModelTerminal(float reward);
    void plan(const StepConstants& k, const std::uint8_t* allowed);  // allowed: the step's action mask
    void recordModelError(float error);
    // Room for everything an update with `features` RBFs, `active` of them in its lookup, may
    // need (scratch, traces, weights). Called before anything changes: an allocation failure
    // then leaves the agent as it was.
    void reserveFor(std::uint32_t features, std::size_t active);
    void reserveBody(std::uint32_t features, std::size_t active);  // the same without the brain's part
    // The reward of the step that ends now, within [-1, 1] (a clamp is counted and reported, once
    // per agent); a learning agent adds it to its brain's reward range (`final`: a trial's end).
    float learnedReward(float reward, bool final = false);
    float clampedReward(float reward);  // the same without adding it to the brain's range
    // A batch's bodies of one brain, on several threads at once (shared_step.cpp): prepareShared
    // makes the step against the brain as it is, keeping its weight changes (no write to the
    // brain; false: the step would grow or plan, and is made whole later) and what the brain's
    // measures are to see in `seen`; commitShared adds that to the brain (in body order), then
    // td.trainPart trains the weights.
    struct SharedStep {
        bool seesReward = false, seesDelta = false, learns = false;
        float reward = 0.0f, delta = 0.0f;
        float eta = 0.0f;  // the critic's rate, for Adaptation::GroupRates
    };
    bool prepareShared(float reward, ObservationView obs, float dt, core::LookupScratch& scratch, std::uint32_t parts,
                       SharedStep& seen);
    // What `body` saw, into its brain's measures (called in body order).
    static void commitShared(BrainState& brain, const SharedStep& seen, const Impl& body);
    // An update that needed an RBF the budget did not allow: counted and reported (once).
    void noteBudgetReached();
    // probabilities: chooseAction's activations, divided by their sum (uniform over the allowed
    // actions if the sum is not finite, or if `uniform`: the choice ignored them).
    void recordProbabilities(const std::uint8_t* allowed, bool uniform);
    // A crowd's batch asks for the memory of the agents it updates next (batch.cpp), in stages:
    // stage s + 1 follows only pointers that stage s asked for (this, then the brain and the
    // short-term memory, then the weights and the representation's chain). A hint: no effect.
    static constexpr unsigned kPrefetchStages = 2 + core::StateRepresentation::kPrefetchStages;
    void prefetch(unsigned stage) const noexcept;
    // The same for a batch's check of every agent before its updates (batch.cpp), which reads the
    // descriptor: stage 0 asks for the members that lead to the brain, stage 1 for the brain's
    // lines up to the descriptor.
    void prefetchCheck(unsigned stage) const noexcept;
    // And from inside the update before it (core::PrefetchQueue): the arrays an update reads
    // through, in the order it reads them (centres, weights, live list, traces); with
    // `brainToo` false only the body's own (the update before used the same brain).
    void addArraysTo(core::PrefetchQueue& q, bool brainToo) const noexcept;
    static constexpr float kModelErrorAveraging = 0.05f;  // stats.modelError: ~20-step running mean
    bool learnsFromRealSteps() const { return !desc.planning || desc.learnFromRealSteps; }

    std::shared_ptr<BrainState> brain;
    // The brain's, by reference: a body reads and trains the weights every body of its brain shares.
    AgentDescriptor& desc;
    core::StateRepresentation& rep;
    core::WeightTable& weights;
    // Other bodies change the shared weights between two updates of this one.
    bool sharesBrain = false;
    core::Rng rng;
    bool learning = true;
    ActionSelection selection = ActionSelection::Sample;
    core::PrefetchQueue* ahead = nullptr;  // a batch's next agent, during one update (batch.cpp)
    std::uint64_t batchCall = 0;  // the latest batch call that met this body (batch.cpp)
    // Of the latest update's choice; chooseAction's scratch before that (capacity 1 + numActions),
    // so that an update writes one small block where it wrote two.
    std::vector<float> probabilities;

    // Short-term memory: the previous step.
    bool hasPrevious = false;
    std::vector<core::ActiveFeature> previous;
    std::uint32_t previousAction = 0;
    std::vector<std::int32_t> previousDiscrete;
    std::vector<float> previousContinuous;
    float lastDt = 0.1f;  // dt of the latest update: the duration of a terminal transition
    float trialSeconds = 0.0f;  // learning updates' dt since the trial began
    core::RewardStretch stretch;  // the trial's stretches of an unchanged step reward (the horizon's)

    // V(s) of the latest state as the weights give it; stats.value reports it within the value
    // bounds, as every TD error uses it.
    float latestValue = 0.0f;
    AgentStats stats;
    bool reportedClamp = false;
    bool reportedBudget = false;

    // Scratch reused on every update (no allocation once warmed up).
    std::vector<core::ActiveFeature> current;
    std::vector<float> normalized;  // swaps buffers with previousContinuous after each update
    core::TdLearner td;  // its tail is cold: next to the planning state

    // Planning only (desc.planning): last, so that the fields above, which every update reads,
    // share as few cache lines as they can (a crowd's update misses each line it touches).
    core::PredictiveModel model;
    core::Planner planner;
    // What the agent did over the last seconds, for a teacher's judgements (Agent::teach); cold until
    // the first one.
    core::TeacherMemory teacher;
    // Continuous actions (desc.continuousActions): their latest values and noise.
    core::ContinuousActions continuous;
    // Adaptation::GroupRates only: the step's features as mark() takes them (markStep), and a
    // batch's gradient of this body's step, applied in body order (core/shared_step.cpp).
    std::vector<core::ActiveFeature> scaled;
    std::vector<float> groupGradient;
};

core::WeightLayout weightLayoutFor(const AgentDescriptor& desc);

// agent_snapshot.cpp: rebuilds an agent from a snapshot (validating every field), and writes
// what a brain holds (descriptor, RBFs, weights) into a snapshot.
std::unique_ptr<Agent::Impl> restoreAgent(const AgentSnapshot& snapshot);
void snapshotBrain(const BrainState& brain, AgentSnapshot& out);

}  // namespace verve
