#include "tasks/classic/solve_run.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "tasks/classic/acrobot_v1.hpp"
#include "tasks/classic/cart_pole_v1.hpp"
#include "tasks/classic/mountain_car_v0.hpp"
#include "tasks/classic/pendulum_v1.hpp"
#include "verve/agent.hpp"

namespace verve::tasks {

double SolveRun::lastMean(std::size_t window) const {
    const std::size_t n = std::min(window, returns.size());
    if (n == 0) return 0.0;
    return std::accumulate(returns.end() - static_cast<std::ptrdiff_t>(n), returns.end(), 0.0) / static_cast<double>(n);
}

SolveRun trainOnClassicTask(ClassicTask& task, AgentDescriptor descriptor, std::uint64_t budget, std::uint64_t seed,
                            bool stopWhenSolved) {
    descriptor.seed = seed;
    Agent agent(descriptor);
    Observation obs(descriptor);
    const float dt = task.agentStep();
    SolveRun run;
    double windowSum = 0.0;  // the returns of the last 100 episodes
    for (std::uint64_t episode = 0; run.steps < budget; ++episode) {
        task.beginTrial(mixSeed(seed, episode));
        float reward = 0.0f;
        double episodeReturn = 0.0;
        bool ended = false;
        for (std::uint32_t t = 0; t < task.maxStepsPerTrial() && run.steps < budget; ++t) {
            task.observe(obs);
            const std::uint32_t action = agent.update(reward, obs, dt);
            const StepResult step = task.actContinuous(action, agent.continuousAction());
            ++run.steps;
            episodeReturn += task.gymnasiumReward();
            reward = step.reward;
            if (step.terminal) {
                agent.endEpisode(reward);
                ended = true;
                break;
            }
            if (t + 1 == task.maxStepsPerTrial()) {
                agent.truncateEpisode(reward);
                ended = true;
            }
        }
        if (!ended) break;  // the budget ran out mid-episode
        run.returns.push_back(episodeReturn);
        run.endSteps.push_back(run.steps);
        windowSum += episodeReturn;
        if (run.returns.size() > 100) windowSum -= run.returns[run.returns.size() - 101];
        if (run.stepsToSolve == 0 && run.returns.size() >= 100 && windowSum / 100.0 >= task.solvedReturn()) {
            run.stepsToSolve = run.steps;
            if (stopWhenSolved) break;
        }
    }
    return run;
}

const std::vector<ClassicInfo>& classicTasks() {
    static const std::vector<ClassicInfo> tasks{
        {"cart-pole-v1", [] { return std::make_unique<CartPoleV1>(); }},
        {"acrobot-v1", [] { return std::make_unique<AcrobotV1>(); }},
        {"mountain-car-v0", [] { return std::make_unique<MountainCarV0>(); }},
        {"pendulum-v1", [] { return std::make_unique<PendulumV1>(); }},
        {"pendulum-v1-continuous", [] { return std::make_unique<PendulumV1>(PendulumV1::Torque::Continuous); }},
    };
    return tasks;
}

const ClassicInfo* findClassicTask(const std::string& name) {
    for (const ClassicInfo& info : classicTasks()) {
        if (name == info.name) return &info;
    }
    return nullptr;
}

}  // namespace verve::tasks
