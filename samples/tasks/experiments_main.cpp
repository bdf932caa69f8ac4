// verve-experiments: runs a thesis task at full size (the original library's runs x trials by
// default) and prints the mean learning curve as CSV.
//   verve-experiments list
//   verve-experiments run hot-plate-1d [--runs 300] [--trials 31] [--csv curve.csv] ...
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>

#include "tasks/registry.hpp"
#include "tasks/settings.hpp"

namespace {

using verve::tasks::LearningCurve;

void writeCsv(std::ostream& out, const LearningCurve& c) {
    out << "trial,steps,reward,optimal_steps,success,terminal\n";
    for (std::size_t t = 0; t < c.trials(); ++t) {
        out << t << ',' << c.steps[t] << ',' << c.reward[t] << ',' << c.optimalSteps[t] << ',' << c.success[t]
            << ',' << c.terminal[t] << '\n';
    }
}

// First and last 10% of the trials (at least one trial each), the windows the original reported.
void printSummary(const verve::tasks::TaskInfo& info, const LearningCurve& c, double seconds) {
    const std::size_t n = c.trials();
    const std::size_t w = std::max<std::size_t>(1, n / 10);
    auto line = [&](const char* label, const std::vector<double>& v) {
        std::printf("# %-14s first %zu trials %10.4f   last %zu trials %10.4f\n", label, w,
                    verve::tasks::windowMean(v, 0, w), w, verve::tasks::windowMean(v, n - w, n));
    };
    std::printf("# task %s: %u runs x %zu trials in %.1f s (metric: %s)\n", info.name.c_str(), c.runs, n, seconds,
                verve::tasks::metricName(info.metric));
    line("steps", c.steps);
    line("optimal steps", c.optimalSteps);
    line("reward", c.reward);
    line("success", c.success);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Runs Verve's thesis tasks and prints mean learning curves"};
    app.require_subcommand(1);

    CLI::App* list = app.add_subcommand("list", "List the tasks");

    CLI::App* run = app.add_subcommand("run", "Run one task and print its curve as CSV");
    std::string taskName;
    std::optional<std::uint32_t> runs, trials;
    std::uint64_t seed = 1;
    unsigned threads = 0;
    std::string csvPath;
    std::optional<float> policyMultiplier, tauValue, policyWeightBound;
    std::optional<std::uint32_t> resolution, maxPlanningSteps;
    std::optional<bool> planning;
    std::optional<verve::CuriosityMode> curiosity;
    std::optional<verve::RbfAllocation> allocation;
    const std::map<std::string, verve::CuriosityMode> curiosityModes{
        {"none", verve::CuriosityMode::None}, {"novelty", verve::CuriosityMode::Novelty},
        {"progress", verve::CuriosityMode::Progress}};
    const std::map<std::string, verve::RbfAllocation> allocations{{"dynamic", verve::RbfAllocation::Dynamic},
                                                                  {"full", verve::RbfAllocation::Full}};
    run->add_option("task", taskName, "Task name (see `list`)")->required();
    run->add_option("--runs", runs, "Independent runs (default: the task's full size)")->check(CLI::PositiveNumber);
    run->add_option("--trials", trials, "Trials per run (default: the task's full size)")
        ->check(CLI::PositiveNumber);
    run->add_option("--seed", seed, "Base seed");
    run->add_option("--threads", threads, "Worker threads (0: all hardware threads)");
    run->add_option("--csv", csvPath, "Write the curve here instead of stdout");
    run->add_option("--policy-multiplier", policyMultiplier, "Override the policy learning multiplier")
        ->check(CLI::PositiveNumber);
    run->add_option("--tau-value", tauValue, "Override the critic's time constant (seconds)")
        ->check(CLI::NonNegativeNumber);
    run->add_option("--policy-weight-bound", policyWeightBound, "Override the actor weight bound (0: unbounded)")
        ->check(CLI::NonNegativeNumber);
    run->add_option("--resolution", resolution, "Override the continuous resolution")->check(CLI::PositiveNumber);
    run->add_option("--planning", planning, "Override planning (true/false)");
    run->add_option("--max-planning-steps", maxPlanningSteps, "Override the planning step cap");
    run->add_option("--curiosity", curiosity, "Override curiosity: none, novelty, progress")
        ->transform(CLI::CheckedTransformer(curiosityModes, CLI::ignore_case));
    run->add_option("--allocation", allocation, "Override RBF allocation: dynamic, full")
        ->transform(CLI::CheckedTransformer(allocations, CLI::ignore_case));

    bool libraryDefaults = false;
    std::vector<std::string> settings;
    run->add_flag("--defaults", libraryDefaults,
                  "Every learning setting at the library's default: only the task's sensors, actions and features");
    run->add_option("--set", settings, "A setting by its C ABI name, e.g. tau_discount=2 (after --defaults)");

    CLI11_PARSE(app, argc, argv);

    if (list->parsed()) {
        for (const auto& info : verve::tasks::taskRegistry()) {
            std::printf("%-34s %4u x %-5u %-8s %s\n", info.name.c_str(), info.runs, info.trials,
                        verve::tasks::metricName(info.metric), info.description.c_str());
        }
        return 0;
    }

    const verve::tasks::TaskInfo* info = verve::tasks::findTask(taskName);
    if (info == nullptr) {
        std::fprintf(stderr, "error: no task named '%s' (see `verve-experiments list`)\n", taskName.c_str());
        return 2;
    }
    auto overrides = [&](verve::AgentDescriptor& d) {
        if (libraryDefaults) d = verve::tasks::atLibraryDefaults(d);
        for (const auto& s : settings) verve::tasks::applySetting(d, s);
        if (policyMultiplier) d.policyMultiplier = *policyMultiplier;
        if (resolution) d.resolution = *resolution;
        if (planning) d.planning = *planning;
        if (maxPlanningSteps) d.maxPlanningSteps = *maxPlanningSteps;
        if (curiosity) d.curiosity = *curiosity;
        if (allocation) d.allocation = *allocation;
        if (tauValue) d.tauValue = *tauValue;
        if (policyWeightBound) d.policyWeightBound = *policyWeightBound;
    };

    try {
        const auto start = std::chrono::steady_clock::now();
        const LearningCurve curve = verve::tasks::runExperiment(info->make, runs.value_or(info->runs),
                                                                trials.value_or(info->trials), seed, overrides,
                                                                threads);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        printSummary(*info, curve, seconds);
        if (csvPath.empty()) {
            writeCsv(std::cout, curve);
        } else {
            std::ofstream file(csvPath);
            if (!file) {
                std::fprintf(stderr, "error: cannot write %s\n", csvPath.c_str());
                return 1;
            }
            writeCsv(file, curve);
            std::printf("# curve written to %s\n", csvPath.c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
