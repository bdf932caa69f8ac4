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

    // Ends a trial: `finalReward` is terminal (no value is bootstrapped past it), then the
    // short-term memory is cleared. The next update starts a fresh trial.
    void endEpisode(float finalReward);

    // Forgets the previous step and all eligibility traces; keeps everything learned.
    void resetShortTermMemory();

    // Off: the policy still acts, nothing learns, no RBFs are allocated, no model or planning runs.
    void setLearning(bool enabled);
    bool learning() const;

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
