#include "learning_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "progress.hpp"
#include "tasks/task_rng.hpp"

namespace verve::demo {

namespace {

std::string describe(const Runnable& r, std::uint32_t run, std::uint32_t runs, double last, double best,
                     double recent) {
    char text[200];
    std::snprintf(text, sizeof text, "run %u/%u | last %.3g | best %.3g | recent mean %.3g (%s)", run, runs,
                  last, best, recent, r.metricLabel.c_str());
    return text;
}

}  // namespace

LearningOutcome runLearning(const Runnable& runnable, const LearningOptions& options) {
    const std::uint32_t trials = options.trials > 0 ? options.trials : runnable.trials;
    LearningOutcome outcome;
    const auto start = std::chrono::steady_clock::now();
    for (std::uint32_t run = 0; run < options.runs; ++run) {
        const std::uint64_t runSeed = tasks::mixSeed(options.seed, run);
        std::unique_ptr<tasks::Environment> env = runnable.make(runSeed);
        AgentDescriptor desc = env->agentDescriptor();
        desc.seed = runSeed;
        if (options.overrides) options.overrides(desc);
        auto agent = std::make_unique<Agent>(desc);

        std::vector<double> metric;
        std::uint32_t solvedAt = 0;
        double best = runnable.higherIsBetter ? -1e300 : 1e300;
        Progress progress(trials);
        for (std::uint32_t t = 0; t < trials; ++t) {
            const tasks::TrialResult result = tasks::runTrial(*agent, *env, tasks::mixSeed(runSeed, t));
            outcome.agentSteps += result.steps;
            const double value = runnable.metric(result, *env);
            metric.push_back(value);
            const bool record = runnable.higherIsBetter ? value > best : value < best;
            if (record) best = value;
            const std::size_t window = std::min<std::size_t>(metric.size(), 10);
            const double recent = tasks::windowMean(metric, metric.size() - window, metric.size());
            const bool solved = runnable.capMeansSolved && !result.terminal && result.steps >= env->maxStepsPerTrial();
            progress.update(t + 1, describe(runnable, run + 1, options.runs, value, best, recent),
                            record && runnable.capMeansSolved);
            if (run == 0 && std::find(options.valueAt.begin(), options.valueAt.end(), t + 1) != options.valueAt.end()) {
                if (auto image = sampleValueImage(*agent, runnable.sensorNames))
                    outcome.snapshots.push_back({t + 1, std::move(*image)});
            }
            if (solved && solvedAt == 0) {
                solvedAt = t + 1;
                if (options.stopWhenSolved) {
                    progress.update(t + 1, describe(runnable, run + 1, options.runs, value, best, recent) +
                                               " | SOLVED", true);
                    break;
                }
            }
        }
        progress.finish();
        outcome.metric.push_back(std::move(metric));
        outcome.solvedAt.push_back(solvedAt);
        if (run == 0) outcome.agent = std::move(agent);
    }
    outcome.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return outcome;
}

}  // namespace verve::demo
