// A learning run of one agent in one environment, trial by trial, with a progress line: what
// tasks::runExperiment does in bulk, plus progress, early stop and value snapshots for the demo.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "catalog.hpp"
#include "value_image.hpp"

namespace verve::demo {

struct LearningOptions {
    std::uint32_t runs = 1;
    std::uint32_t trials = 0;  // 0: the runnable's default
    std::uint64_t seed = 1;
    tasks::DescriptorOverride overrides;
    std::vector<std::uint32_t> valueAt;  // after these trials (1-based) of run 1, snapshot V
    bool stopWhenSolved = true;          // capMeansSolved runnables: stop a run at its first solved trial
};

struct ValueSnapshot {
    std::uint32_t trial;
    ValueImage image;
};

struct LearningOutcome {
    std::vector<std::vector<double>> metric;  // [run][trial]; shorter when a run stopped early
    std::vector<std::uint32_t> solvedAt;      // per run: 1-based trial that reached the cap, 0 if none
    std::unique_ptr<Agent> agent;             // run 1's agent, trained
    std::vector<ValueSnapshot> snapshots;     // run 1's, in trial order
    double wallSeconds = 0.0;
    std::uint64_t agentSteps = 0;
};

// Same seeds as tasks::runExperiment: run r uses mixSeed(seed, r) for the environment and agent,
// trial t uses mixSeed(runSeed, t).
LearningOutcome runLearning(const Runnable& runnable, const LearningOptions& options);

}  // namespace verve::demo
