#include "tasks/driver.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "tasks/task.hpp"
#include "tasks/task_rng.hpp"

namespace verve::tasks {

TrialResult runTrial(Agent& agent, Environment& env, std::uint64_t seed) {
    TrialResult result;
    env.beginTrial(seed);
    const auto* task = dynamic_cast<const Task*>(&env);
    if (task != nullptr) {
        result.optimalSteps = task->optimalSteps();
        if (task->finishedAtStart()) {
            result.terminal = true;
            result.succeeded = task->succeeded();
            return result;
        }
    }

    Observation obs(agent.descriptor());
    const float dt = env.agentStep();
    const std::uint32_t cap = env.maxStepsPerTrial();
    const bool continuing = task != nullptr && task->continuing();
    float reward = continuing ? task->carriedReward() : 0.0f;
    while (result.steps < cap) {
        env.observe(obs);
        const std::uint32_t action = agent.update(reward, obs, dt);
        const StepResult step = env.actContinuous(action, agent.continuousAction());
        ++result.steps;
        result.rewardSum += step.reward;
        if (step.terminal) {
            agent.endEpisode(step.reward);
            result.terminal = true;
            break;
        }
        reward = step.reward;
    }
    // Cut off at the cap: the last reward is learned, bootstrapped from the last state's value.
    if (!result.terminal && !continuing) {
        if (task == nullptr || task->truncatesAtCap()) {
            agent.truncateEpisode(reward);
        } else {
            agent.resetShortTermMemory();
        }
    }
    if (task != nullptr) result.succeeded = task->succeeded();
    return result;
}

double windowMean(const std::vector<double>& values, std::size_t first, std::size_t last) {
    last = std::min(last, values.size());
    if (first >= last) throw std::out_of_range("windowMean: empty window");
    double sum = 0.0;
    for (std::size_t i = first; i < last; ++i) sum += values[i];
    return sum / static_cast<double>(last - first);
}

namespace {

std::vector<TrialResult> runOne(const TaskFactory& makeTask, std::uint32_t trials, std::uint64_t runSeed,
                                const DescriptorOverride& overrides) {
    std::unique_ptr<Environment> env = makeTask(runSeed);
    if (!env) throw std::invalid_argument("runExperiment: the task factory returned nothing");
    AgentDescriptor desc = env->agentDescriptor();
    desc.seed = runSeed;
    if (overrides) overrides(desc);
    Agent agent(desc);
    std::vector<TrialResult> results;
    results.reserve(trials);
    for (std::uint32_t t = 0; t < trials; ++t) results.push_back(runTrial(agent, *env, mixSeed(runSeed, t)));
    return results;
}

}  // namespace

LearningCurve runExperiment(const TaskFactory& makeTask, std::uint32_t runs, std::uint32_t trials,
                            std::uint64_t baseSeed, const DescriptorOverride& overrides, unsigned threads) {
    if (!makeTask) throw std::invalid_argument("runExperiment: no task factory");
    if (runs == 0 || trials == 0) throw std::invalid_argument("runExperiment: runs and trials must be >= 1");
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = std::min<unsigned>(threads, runs);

    // Runs are independent (own environment, own agent); each thread takes the next run index.
    std::vector<std::vector<TrialResult>> perRun(runs);
    std::atomic<std::uint32_t> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    auto worker = [&] {
        for (std::uint32_t r = next++; r < runs; r = next++) {
            try {
                perRun[r] = runOne(makeTask, trials, mixSeed(baseSeed, r), overrides);
            } catch (...) {
                std::lock_guard<std::mutex> lock(failureMutex);
                if (!failure) failure = std::current_exception();
                next = runs;  // stop handing out work
            }
        }
    };
    std::vector<std::thread> pool;
    for (unsigned i = 1; i < threads; ++i) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);

    // Summed in run order so the curve does not depend on scheduling.
    LearningCurve curve;
    curve.runs = runs;
    for (auto* v : {&curve.steps, &curve.reward, &curve.optimalSteps, &curve.success, &curve.terminal}) {
        v->assign(trials, 0.0);
    }
    for (const auto& results : perRun) {
        for (std::uint32_t t = 0; t < trials; ++t) {
            const TrialResult& r = results[t];
            curve.steps[t] += r.steps;
            curve.reward[t] += r.rewardSum;
            curve.optimalSteps[t] += r.optimalSteps;
            curve.success[t] += r.succeeded ? 1.0 : 0.0;
            curve.terminal[t] += r.terminal ? 1.0 : 0.0;
        }
    }
    const double n = runs;
    for (auto* v : {&curve.steps, &curve.reward, &curve.optimalSteps, &curve.success, &curve.terminal}) {
        for (double& x : *v) x /= n;
    }
    return curve;
}

}  // namespace verve::tasks
