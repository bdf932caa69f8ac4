// The learning agent: hand it a reward and what its sensors read, it answers with an action.
// Thread rules: one Agent is used by one thread at a time; different Agents are independent.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "verve/agent_descriptor.hpp"
#include "verve/agent_snapshot.hpp"
#include "verve/error.hpp"
#include "verve/observation.hpp"

namespace verve {

struct AgentStats {
    std::uint64_t steps = 0;            // real updates since creation
    std::uint32_t rbfCount = 0;         // features allocated so far
    std::uint32_t liveTraces = 0;       // eligibility traces above the threshold
    float value = 0.0f;                 // V(s) of the latest observation
    float tdError = 0.0f;               // TD error of the latest real step
    float modelError = 0.0f;            // running mean squared prediction error of the model
    float predictedUncertainty = 0.0f;  // the model's own uncertainty at the latest step
    std::uint32_t planningSteps = 0;    // imagined steps after the latest real step
    float curiosityReward = 0.0f;       // curiosity reward summed over the latest plan
    std::uint64_t rbfBudgetHits = 0;    // updates that would have added an RBF beyond maxRbfs
    std::uint64_t clampedRewards = 0;   // rewards outside [-1, 1] that were clamped
};

// How update() picks the action from the policy's probabilities.
enum class ActionSelection : std::uint8_t {
    Sample = 0,  // roulette: each action with its probability (learning explores; the default)
    Greedy = 1,  // always the most probable action: deterministic play for a shipped NPC
};

// Which actions the agent may choose on one step: `count` flags (numActions), 1 allowed, 0 not;
// with action branches one flag per choice of each branch (AgentDescriptor::actionChoices()).
struct ActionMask {
    const std::uint8_t* allowed = nullptr;
    std::size_t count = 0;
};

// The continuous action values a teacher chose on a demonstrated step (docs/teaching.md): one per
// AgentDescriptor::continuousActions, each in [-1, 1].
struct ContinuousActionView {
    const float* values = nullptr;
    std::uint32_t count = 0;
};

enum class SensorKind : std::uint8_t { Discrete = 0, Continuous = 1 };

// One axis of a value-function image: a sensor swept over its range.
struct ValueAxis {
    SensorKind kind = SensorKind::Continuous;
    std::uint32_t index = 0;    // which discrete or continuous sensor
    std::uint32_t samples = 0;  // continuous: points from -1 to 1; discrete: must equal its value count
};

class Agent {
public:
    explicit Agent(const AgentDescriptor& descriptor);  // throws Error(InvalidArgument)
    explicit Agent(const AgentSnapshot& snapshot);      // throws Error(Format) if inconsistent
    ~Agent();
    Agent(Agent&&) noexcept;
    Agent& operator=(Agent&&) noexcept;
    Agent(const Agent&) = delete;
    Agent& operator=(const Agent&) = delete;

    // One step: `reward` is what the previous action earned (clamped to [-1, 1]); `obs` is the
    // state now; `dt` seconds passed since the previous update. Returns the action to take.
    // Invalid input throws Error(InvalidArgument) and leaves the agent unchanged.
    std::uint32_t update(float reward, const Observation& obs, float dt);
    std::uint32_t update(float reward, ObservationView obs, float dt);
    // The same step, choosing only among the actions `mask` allows (at least one; each flag 0 or
    // 1). A masked action is never chosen and so gets no credit. Imagined planning steps are not
    // masked: the mask says what is possible now, not later.
    std::uint32_t update(float reward, ObservationView obs, float dt, ActionMask mask);
    // A demonstrated step (docs/teaching.md): as update, but the host took `action` (a player or a
    // scripted AI drove the NPC). The agent learns from it as from its own choice and is pulled
    // towards it; the next plain update acts on its own again. `action` must be one the mask
    // allows (any, without a mask); a refused call changes nothing.
    void updateDemonstrated(float reward, ObservationView obs, float dt, std::uint32_t action, ActionMask mask = {});
    // The same with the teacher's continuous actions too (one value per continuous action, each in
    // [-1, 1]): the agent learns from them as from values it drew itself and is pulled towards them
    // (without them, the step plays the policy's means). A wrong count, NaN or a value outside
    // [-1, 1] is refused (Error(InvalidArgument)) and changes nothing.
    void updateDemonstrated(float reward, ObservationView obs, float dt, std::uint32_t action,
                            ContinuousActionView continuousAction, ActionMask mask = {});

    // Ends a trial: `finalReward` is terminal (no value is bootstrapped past it), then the
    // short-term memory is cleared. The next update starts a fresh trial.
    void endEpisode(float finalReward);

    // Ends a trial that was cut off (a time limit), not finished: `reward` is what the last action
    // earned, and the value of the last state seen stands in for the state it led to, so the trial
    // is not learned as if it had ended there (Gymnasium's `truncated`). Then, as endEpisode, the
    // short-term memory is cleared. The predictive model learns nothing from it (no next state).
    void truncateEpisode(float reward);

    // A teacher's judgement (docs/teaching.md): `praise` in [-1, 1], 1 good, -1 bad, of what the agent
    // did over the last 2.5 s (a person reacts 0.2-2 s after the act they judge). It moves the
    // actor's preferences for those acts; it is not a reward. The agent remembers its acts from
    // its first judgement on (praise 0 arms the memory without judging); the memory is not saved.
    void teach(float praise);

    // Forgets the previous step and all eligibility traces; keeps everything learned.
    void resetShortTermMemory();

    // Off: the policy still acts, nothing learns, no RBFs are allocated, no model or planning runs.
    void setLearning(bool enabled);
    bool learning() const;

    // Per agent, not saved with it; Sample by default.
    void setActionSelection(ActionSelection mode);
    ActionSelection actionSelection() const;
    // The policy's probability of each action at the latest update (numActions values, summing to
    // 1; 0 for masked actions), what Sample mode drew from; before any update, uniform. With action
    // branches, each branch's choices in turn (actionChoices() values), each branch summing to 1.
    const std::vector<float>& actionProbabilities() const;
    // The continuous actions of the latest update (AgentDescriptor::continuousActions values, each
    // in [-1, 1]): sampled around the policy's mean, or the mean itself with Greedy selection or on a
    // demonstrated step (the teacher's values, when the step carried them). Before any update, 0s.
    const std::vector<float>& continuousAction() const;

    const AgentDescriptor& descriptor() const;
    AgentStats stats() const;
    float valueEstimate() const;
    float tdError() const;
    std::size_t rbfCount() const;

    // Samples V over 1 or 2 swept sensors, the others held at `base`. Writes
    // axes[0].samples * axes[1].samples values, axis 0 fastest. Learns and allocates nothing.
    void sampleValueFunction(const std::vector<ValueAxis>& axes, const Observation& base,
                             float* out, std::size_t outCount) const;

    AgentSnapshot snapshot() const;

    struct Impl;  // internal (src/core/agent_impl.hpp)

private:
    friend class Brain;  // makes bodies: agents over a shared brain
    friend class Batch;  // groups agents by brain
    explicit Agent(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace verve
