// An environment an agent learns in: the thesis's discrete tasks (this folder) and the Bullet
// scenes (samples/scenes) both implement it, so tests, benchmarks and the runner drive any of them.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "verve/agent_descriptor.hpp"
#include "verve/observation.hpp"

namespace verve::tasks {

struct StepResult {
    float reward = 0.0f;
    bool terminal = false;  // the trial ends here; reward is the final reward
};

class Environment {
public:
    virtual ~Environment() = default;

    virtual std::string name() const = 0;
    // Sensors and actions, with the thesis's agent settings for this task as defaults.
    virtual AgentDescriptor agentDescriptor() const = 0;
    virtual float agentStep() const { return 0.1f; }      // dt handed to Agent::update, seconds
    virtual std::uint32_t maxStepsPerTrial() const = 0;  // a trial is cut off here

    // Starts a trial. All randomness comes from the seed (the same seed, the same trial).
    virtual void beginTrial(std::uint64_t seed) = 0;
    virtual void observe(Observation& out) const = 0;
    virtual StepResult act(std::uint32_t action) = 0;
    // The same with the agent's continuous actions (AgentDescriptor::continuousActions values in
    // [-1, 1]): tasks that have some override it, the others ignore them.
    virtual StepResult actContinuous(std::uint32_t action, const std::vector<float>& continuous) {
        (void)continuous;
        return act(action);
    }
};

}  // namespace verve::tasks
