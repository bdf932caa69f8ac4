// Driving an agent through tasks: one trial, or a whole experiment (many independent runs of many
// trials, averaged into a learning curve). Shared by the learning tests, benchmarks and the CLIs.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "tasks/environment.hpp"
#include "verve/agent.hpp"

namespace verve::tasks {

struct TrialResult {
    std::uint32_t steps = 0;
    double rewardSum = 0.0;          // environment rewards as returned (before the agent clamps)
    bool terminal = false;           // ended in a terminal state; false when cut off at the cap
    std::uint32_t optimalSteps = 0;  // Task::optimalSteps() at the start; 0 when unknown
    bool succeeded = false;          // Task::succeeded() at the end
};

// One trial: the first update gets reward 0, then act/update until the environment says terminal
// (agent.endEpisode(finalReward), no extra update) or the step cap (not terminal:
// agent.truncateEpisode(lastReward) learns the last reward without treating the cut as an end;
// a task that keeps the original's protocol, Task::truncatesAtCap() false, only resets).
TrialResult runTrial(Agent& agent, Environment& env, std::uint64_t seed);

using TaskFactory = std::function<std::unique_ptr<Environment>(std::uint64_t runSeed)>;
using DescriptorOverride = std::function<void(AgentDescriptor&)>;

// Per-trial means over all runs.
struct LearningCurve {
    std::uint32_t runs = 0;
    std::vector<double> steps;
    std::vector<double> reward;        // reward sum per trial
    std::vector<double> optimalSteps;  // mean optimum of the same trials (0 when unknown)
    std::vector<double> success;       // fraction of runs whose trial succeeded
    std::vector<double> terminal;      // fraction of runs whose trial ended terminally

    std::size_t trials() const { return steps.size(); }
};

// Mean of values[first, last) (last is clamped to the size); throws std::out_of_range if empty.
double windowMean(const std::vector<double>& values, std::size_t first, std::size_t last);

// Runs `runs` independent agents for `trials` trials each, spread over `threads` threads
// (0: one per hardware thread). Run r uses run seed mixSeed(baseSeed, r) for both the environment
// and the agent (descriptor.seed) and trial seeds mixSeed(runSeed, t); `overrides` may then adjust
// the task's default descriptor. Same arguments, same curve, whatever the thread count.
LearningCurve runExperiment(const TaskFactory& makeTask, std::uint32_t runs, std::uint32_t trials,
                            std::uint64_t baseSeed, const DescriptorOverride& overrides = {},
                            unsigned threads = 0);

}  // namespace verve::tasks
