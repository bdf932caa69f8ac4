// What a learning test reads from a curve: means over a window of trials, printed so a failing
// (or passing) run shows the numbers to compare with the original library.
#pragma once
#include <cstdio>
#include <string>

#include "tasks/driver.hpp"
#include "tasks/registry.hpp"
#include "tasks/settings.hpp"

namespace verve::tasks::testing {

constexpr std::uint64_t kSeed = 2024;  // fixed: the same curve on every run of the suite

struct Window {
    double steps = 0;
    double optimal = 0;
    double reward = 0;
    double success = 0;
    double excess() const { return steps - optimal; }  // steps above the best possible
};

inline Window windowOf(const LearningCurve& c, std::size_t first, std::size_t last) {
    return Window{windowMean(c.steps, first, last), windowMean(c.optimalSteps, first, last),
                  windowMean(c.reward, first, last), windowMean(c.success, first, last)};
}

// The last tenth of the trials: the window the original's final numbers were taken over.
inline Window lastTenth(const LearningCurve& c) {
    const std::size_t n = c.trials();
    return windowOf(c, n - std::max<std::size_t>(1, n / 10), n);
}

inline LearningCurve learn(const std::string& task, std::uint32_t runs, std::uint32_t trials) {
    const TaskInfo* info = findTask(task);
    if (info == nullptr) throw std::invalid_argument("no task " + task);
    return runExperiment(info->make, runs, trials, kSeed);
}

// The task with only its sensors, actions and features, every learning setting at the library's
// default (as ./scripts/defaults_table.sh runs it: base seed 1, so the numbers are the table's).
inline Window lateAtDefaults(const std::string& task, std::uint32_t runs, std::uint32_t trials, std::size_t first) {
    const TaskInfo* info = findTask(task);
    if (info == nullptr) throw std::invalid_argument("no task " + task);
    const LearningCurve c = runExperiment(info->make, runs, trials, 1, [](AgentDescriptor& d) { d = atLibraryDefaults(d); });
    return windowOf(c, first, trials);
}

inline void print(const std::string& label, const Window& w) {
    std::printf("[ measured ] %s: steps %.3f optimal %.3f excess %.3f reward %.4f success %.4f\n", label.c_str(),
                w.steps, w.optimal, w.excess(), w.reward, w.success);
}

}  // namespace verve::tasks::testing
