// Update time with planning on: a 10x10 discrete maze #2 agent whose model has learned the maze,
// plans capped at 10 and 50 imagined steps (the original: 47 us and 147 us; 0.8 us without); and a
// continuous maze #1 agent, whose plans run only where they reach the goal (a dry run first) and
// then weigh every action at the real state (core/planner.hpp).
#include <benchmark/benchmark.h>

#include "tasks/registry.hpp"
#include "verve/agent.hpp"

using namespace verve;
using namespace verve::tasks;

namespace {

void plannedUpdate(benchmark::State& state, const char* task) {
    auto env = findTask(task)->make(1);
    AgentDescriptor d = env->agentDescriptor();
    d.maxPlanningSteps = static_cast<std::uint32_t>(state.range(0));
    d.planning = state.range(0) > 0;
    Agent agent(d);
    for (std::uint64_t t = 0; t < 30; ++t) runTrial(agent, *env, t);  // warm up: the maze is known
    Observation obs(d);
    env->beginTrial(0);
    float reward = 0.0f;
    std::uint64_t plannedSteps = 0;
    for (auto _ : state) {
        env->observe(obs);
        const std::uint32_t action = agent.update(reward, obs, 0.1f);
        plannedSteps += agent.stats().planningSteps;
        const StepResult step = env->act(action);
        reward = step.reward;
        if (step.terminal) {
            agent.endEpisode(step.reward);
            env->beginTrial(0);
            reward = 0.0f;
        }
    }
    state.counters["plan_steps"] = benchmark::Counter(static_cast<double>(plannedSteps), benchmark::Counter::kAvgIterations);
}

}  // namespace

BENCHMARK_CAPTURE(plannedUpdate, maze2, "maze2-planning")->Arg(0)->Arg(10)->Arg(50)->ArgName("max_planning_steps");
BENCHMARK_CAPTURE(plannedUpdate, maze1_continuous, "maze1-continuous")->Arg(0)->Arg(10)->ArgName("max_planning_steps");
