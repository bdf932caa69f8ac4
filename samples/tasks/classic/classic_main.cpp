// verve-classic: trains agents on Gymnasium's classic control tasks at Verve's defaults (or with
// settings changed by --set) and prints, per seed, the environment steps until the mean return of
// the last 100 episodes reached the task's threshold.
//   verve-classic list
//   verve-classic cart-pole-v1 [--seeds 10] [--first-seed 1] [--budget 300000] [--set tau_discount=2]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "tasks/classic/solve_run.hpp"
#include "tasks/settings.hpp"

namespace {

using verve::AgentDescriptor;

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Trains Verve agents on Gymnasium's classic control tasks at the library's defaults"};
    std::string taskName;
    std::uint32_t seeds = 10;
    std::uint64_t firstSeed = 1, budget = 0;
    unsigned threads = 0;
    std::vector<std::string> settings;
    bool full = false;
    app.add_option("task", taskName, "Task (`list` lists them)")->required();
    app.add_option("--seeds", seeds, "How many seeds")->check(CLI::PositiveNumber);
    app.add_option("--first-seed", firstSeed, "The first seed");
    app.add_option("--budget", budget, "Environment steps per seed (default: 3x the RL Zoo's budget)");
    app.add_option("--threads", threads, "Threads (0: all hardware threads)");
    app.add_option("--set", settings, "A setting changed from the default, e.g. tau_discount=2");
    app.add_flag("--full", full, "Train for the whole budget instead of stopping once solved");
    CLI11_PARSE(app, argc, argv);

    if (taskName == "list") {
        for (const auto& info : verve::tasks::classicTasks()) std::printf("%s\n", info.name);
        return 0;
    }
    const auto* info = verve::tasks::findClassicTask(taskName);
    if (info == nullptr) {
        std::fprintf(stderr, "verve-classic: no task %s (try `verve-classic list`)\n", taskName.c_str());
        return 2;
    }
    auto probe = info->make();
    AgentDescriptor desc = probe->agentDescriptor();
    try {
        for (const auto& s : settings) verve::tasks::applySetting(desc, s);
        desc.validate();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "verve-classic: %s\n", e.what());
        return 2;
    }
    if (budget == 0) budget = 3 * probe->zooBudget();

    std::vector<verve::tasks::SolveRun> runs(seeds);
    std::atomic<std::uint32_t> next{0};
    auto work = [&] {
        for (std::uint32_t i; (i = next++) < seeds;) {
            auto task = info->make();
            runs[i] = verve::tasks::trainOnClassicTask(*task, desc, budget, firstSeed + i, !full);
        }
    };
    const unsigned n = std::max(1u, std::min(threads ? threads : std::thread::hardware_concurrency(), seeds));
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < n; ++t) pool.emplace_back(work);
    for (auto& t : pool) t.join();

    std::printf("# %s, budget %llu steps, threshold %.0f, RL Zoo %s: %llu steps\n", probe->name().c_str(),
                static_cast<unsigned long long>(budget), probe->solvedReturn(), probe->zooAgent(),
                static_cast<unsigned long long>(probe->zooBudget()));
    std::printf("seed,steps_to_solve,episodes,last100_mean\n");
    std::vector<double> solved;
    for (std::uint32_t i = 0; i < seeds; ++i) {
        const auto& r = runs[i];
        std::printf("%llu,%llu,%zu,%.1f\n", static_cast<unsigned long long>(firstSeed + i),
                    static_cast<unsigned long long>(r.stepsToSolve), r.returns.size(), r.lastMean());
        if (r.stepsToSolve > 0) solved.push_back(static_cast<double>(r.stepsToSolve));
    }
    std::sort(solved.begin(), solved.end());
    // Unsolved seeds count as the budget for the median (a lower bound on what they need).
    std::vector<double> all = solved;
    all.resize(seeds, static_cast<double>(budget));
    std::sort(all.begin(), all.end());
    std::printf("# solved %zu of %u; median steps %.0f (unsolved counted as the budget); worst %.0f\n", solved.size(),
                seeds, all[all.size() / 2], all.back());
    return 0;
}
