// Training on a classic control task the way the field reports it: environment steps until the
// mean return of the last 100 episodes first reaches the task's threshold, within a step budget.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "tasks/classic/classic_task.hpp"
#include "verve/agent_descriptor.hpp"

namespace verve::tasks {

struct SolveRun {
    std::vector<double> returns;           // Gymnasium's return of every finished episode
    std::vector<std::uint64_t> endSteps;   // the environment step each of them ended at
    std::uint64_t stepsToSolve = 0;        // 0: not solved within the budget
    std::uint64_t steps = 0;               // steps taken in all
    // Mean return of the last `window` finished episodes (all of them when fewer).
    double lastMean(std::size_t window = 100) const;
};

// One agent (descriptor.seed = seed; episode e starts from mixSeed(seed, e)) trained for up to
// `budget` environment steps; with `stopWhenSolved` it stops at the episode that solves the task.
// Episodes that end terminally end through Agent::endEpisode, those cut by the time limit through
// Agent::truncateEpisode.
SolveRun trainOnClassicTask(ClassicTask& task, AgentDescriptor descriptor, std::uint64_t budget, std::uint64_t seed,
                            bool stopWhenSolved);

using ClassicFactory = std::function<std::unique_ptr<ClassicTask>()>;
struct ClassicInfo {
    const char* name;  // as the CLI and tests name it: cart-pole-v1, acrobot-v1, ...
    ClassicFactory make;
};
const std::vector<ClassicInfo>& classicTasks();
const ClassicInfo* findClassicTask(const std::string& name);

}  // namespace verve::tasks
