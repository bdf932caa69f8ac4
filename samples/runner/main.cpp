// verve-demo: lists and runs the thesis tasks and Bullet scenes headless, prints progress, writes
// a CSV learning curve, PNG plots (gnuplot) and the trained agent (XML).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include "arena_run.hpp"
#include "brain_comparison.hpp"
#include "catalog.hpp"
#include "learning_run.hpp"
#include "plots.hpp"
#include "ray_npc_run.hpp"
#include "scene_registry.hpp"
#include "tasks/settings.hpp"
#include "verve/error.hpp"
#ifdef VERVE_DEMO_HAVE_IO
#include "verve/io.hpp"
#endif

namespace fs = std::filesystem;
using namespace verve;
using namespace verve::demo;

namespace {

struct AgentFlags {
    bool libraryDefaults = false;       // the scene's sensors and actions, every learning setting at its default
    std::vector<std::string> settings;  // key=value by C ABI name, after libraryDefaults
    std::optional<std::uint32_t> resolution;
    std::optional<float> tauValue, tauDiscount, tauEligibility, policyMultiplier;
    bool planning = false;
    std::optional<std::string> curiosity;

    tasks::DescriptorOverride overrides() const {
        return [f = *this](AgentDescriptor& d) {
            if (f.libraryDefaults) d = tasks::atLibraryDefaults(d);
            for (const std::string& s : f.settings) tasks::applySetting(d, s);
            if (f.resolution) d.resolution = *f.resolution;
            if (f.tauValue) d.tauValue = *f.tauValue;
            if (f.tauDiscount) d.tauDiscount = *f.tauDiscount;
            if (f.tauEligibility) d.tauEligibility = *f.tauEligibility;
            if (f.policyMultiplier) d.policyMultiplier = *f.policyMultiplier;
            if (f.planning) d.planning = true;
            if (f.curiosity) {
                d.planning = true;  // curiosity acts through planning
                d.curiosity = *f.curiosity == "progress" ? CuriosityMode::Progress
                              : *f.curiosity == "novelty" ? CuriosityMode::Novelty
                                                           : CuriosityMode::None;
            }
        };
    }
};

struct RunFlags {
    std::string name;
    std::uint64_t seed = 1;
    std::uint32_t trials = 0;
    std::uint32_t runs = 1;
    std::uint32_t npcs = 8;
    std::string out = "demo-out";
    std::vector<std::uint32_t> valueAt;
    bool keepGoing = false;
    bool save = true;
    bool sharedBrain = false;
};

void listAll() {
    std::printf("Bullet scenes:\n");
    for (const Runnable& r : catalog())
        if (r.kind == "scene") std::printf("  %-34s %s (default %u trials)\n", r.name.c_str(), r.description.c_str(), r.trials);
    std::printf("  %-34s %s\n", scenes::kNpcArenaName,
                "learning NPCs: capsules seek food and avoid a hazard, one agent each (trials = simulated minutes)");
    std::printf("  %-34s %s\n", "ray-npc (its own command)",
                "raycast NPCs in a cluttered arena, learning at defaults vs scripted steering (verve-demo ray-npc)");
    std::printf("Thesis tasks:\n");
    for (const Runnable& r : catalog())
        if (r.kind == "task") std::printf("  %-34s %s (default %u trials)\n", r.name.c_str(), r.description.c_str(), r.trials);
}

double meanOf(const std::vector<double>& v, std::size_t first, std::size_t last) {
    return tasks::windowMean(v, first, std::min(last, v.size()));
}

void saveTrained(const Agent& agent, const std::string& path) {
#ifdef VERVE_DEMO_HAVE_IO
    saveAgent(agent, path);
    std::printf("  trained agent:  %s\n", path.c_str());
#else
    (void)agent;
    std::printf("  (agent not saved: this build has no verve_io; %s skipped)\n", path.c_str());
#endif
}

void plotValues(const ValueImage& image, const std::string& base, const std::string& title) {
    if (plotValueImage(image, base + ".dat", base + ".png", title))
        std::printf("  value function: %s.png\n", base.c_str());
}

int runArenaCommand(const RunFlags& flags, const AgentFlags& agentFlags) {
    const std::uint32_t minutes = flags.trials > 0 ? flags.trials : 10;
    std::printf("npc-arena: %u NPCs learning for %u simulated minutes (seed %llu)%s\n", flags.npcs, minutes,
                static_cast<unsigned long long>(flags.seed), flags.sharedBrain ? ", one shared brain" : "");
    ArenaOutcome result = runArena(minutes, flags.seed, flags.npcs, agentFlags.overrides(), flags.sharedBrain);
    const std::string base = (fs::path(flags.out) / "npc-arena").string();
    {
        std::ofstream csv(base + "-curve.csv");
        csv << "minute,food_per_npc_minute,hazard_percent\n";
        for (std::size_t m = 0; m < result.foodPerNpcMinute.size(); ++m)
            csv << m + 1 << ',' << result.foodPerNpcMinute[m] << ',' << result.hazardPercent[m] << '\n';
        if (!csv) throw std::runtime_error("cannot write " + base + "-curve.csv");
    }
    std::printf("Learned in %.1f s of wall time: food per NPC-minute %.2f -> %.2f, time in hazard %.1f%% -> %.1f%%\n",
                result.wallSeconds, result.foodPerNpcMinute.front(), result.foodPerNpcMinute.back(),
                result.hazardPercent.front(), result.hazardPercent.back());
    std::printf("  learning curve: %s-curve.csv\n", base.c_str());
    // Two series of different units: one plot each.
    writeCurveCsv(base + "-food.csv", {{"food_per_npc_minute", result.foodPerNpcMinute}});
    writeCurveCsv(base + "-hazard.csv", {{"hazard_percent", result.hazardPercent}});
    if (plotCurve(base + "-food.csv", base + "-food.png", "NPC arena: food eaten", "simulated minute",
                  "food per NPC per minute", 1))
        std::printf("  plot:           %s-food.png\n", base.c_str());
    if (plotCurve(base + "-hazard.csv", base + "-hazard.png", "NPC arena: time in the hazard zone",
                  "simulated minute", "% of NPC time in hazard", 1))
        std::printf("  plot:           %s-hazard.png\n", base.c_str());
    if (auto image = sampleValueImage(result.arena->agent(0), {"bearing to food (x 180 deg)", "distance to food"}))
        plotValues(*image, base + "-value", "NPC 0 value, hazard clear (discrete sensor 0 = 0)");
    if (flags.save)
        for (std::size_t i = 0; i < result.arena->npcCount(); ++i)
            saveTrained(result.arena->agent(i), base + "-agent" + std::to_string(i) + ".xml");
    return 0;
}

int runCommand(const RunFlags& flags, const AgentFlags& agentFlags) {
    fs::create_directories(flags.out);
    if (flags.name == scenes::kNpcArenaName) return runArenaCommand(flags, agentFlags);
    const Runnable* runnable = findRunnable(flags.name);
    if (runnable == nullptr) {
        std::fprintf(stderr, "verve-demo: no scene or task named '%s' (see: verve-demo list)\n", flags.name.c_str());
        return 2;
    }
    LearningOptions options;
    options.runs = flags.runs;
    options.trials = flags.trials;
    options.seed = flags.seed;
    options.overrides = agentFlags.overrides();
    options.valueAt = flags.valueAt;
    options.stopWhenSolved = !flags.keepGoing;
    std::printf("%s: %s\n%u run(s) x up to %u trials, seed %llu\n", runnable->name.c_str(),
                runnable->description.c_str(), flags.runs, flags.trials > 0 ? flags.trials : runnable->trials,
                static_cast<unsigned long long>(flags.seed));
    LearningOutcome result = runLearning(*runnable, options);

    const std::string base = (fs::path(flags.out) / runnable->name).string();
    std::vector<CurveSeries> series;
    for (std::size_t r = 0; r < result.metric.size(); ++r)
        series.push_back({"run" + std::to_string(r + 1), result.metric[r]});
    writeCurveCsv(base + "-curve.csv", series);

    // Summary: the first and last ten trials of every run, and which trial solved it.
    std::vector<double> first, last;
    for (const auto& m : result.metric) {
        first.push_back(meanOf(m, 0, 10));
        last.push_back(meanOf(m, m.size() - std::min<std::size_t>(m.size(), 10), m.size()));
    }
    std::printf("Learned (%s, mean over %zu run(s)): first 10 trials %.3g -> last 10 trials %.3g\n",
                runnable->metricLabel.c_str(), result.metric.size(), meanOf(first, 0, first.size()),
                meanOf(last, 0, last.size()));
    if (runnable->capMeansSolved) {
        for (std::size_t r = 0; r < result.solvedAt.size(); ++r) {
            if (result.solvedAt[r] > 0)
                std::printf("  run %zu: reached the full trial (%.0f s) at trial %u\n", r + 1,
                            result.metric[r][result.solvedAt[r] - 1], result.solvedAt[r]);
            else
                std::printf("  run %zu: not solved in %zu trials (best %.1f)\n", r + 1, result.metric[r].size(),
                            *std::max_element(result.metric[r].begin(), result.metric[r].end()));
        }
    }
    std::printf("  %llu agent steps in %.1f s of wall time\n", static_cast<unsigned long long>(result.agentSteps),
                result.wallSeconds);
    std::printf("  learning curve: %s-curve.csv\n", base.c_str());
    if (plotCurve(base + "-curve.csv", base + "-curve.png", runnable->name + " learning curve", "trial",
                  runnable->metricLabel, series.size(), runnable->capMeansSolved))
        std::printf("  plot:           %s-curve.png\n", base.c_str());
    for (const ValueSnapshot& s : result.snapshots)
        plotValues(s.image, base + "-value-trial" + std::to_string(s.trial),
                   runnable->name + ": value after trial " + std::to_string(s.trial));
    if (auto image = sampleValueImage(*result.agent, runnable->sensorNames))
        plotValues(*image, base + "-value", runnable->name + ": value after training (run 1)");
    if (flags.save) saveTrained(*result.agent, base + "-agent.xml");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"verve-demo: run Verve's thesis tasks and Bullet scenes headless, with plots"};
    app.require_subcommand(1);
    CLI::App* list = app.add_subcommand("list", "list the scenes and thesis tasks");
    CLI::App* run = app.add_subcommand("run", "run one scene or task and write its curve, plots and agent");
    RunFlags flags;
    AgentFlags agent;
    run->add_option("name", flags.name, "scene or task name (see: list)")->required();
    run->add_option("--seed", flags.seed, "base seed: the same seed, the same run");
    run->add_option("--trials", flags.trials, "trials per run (npc-arena: simulated minutes); 0 = default")
        ->check(CLI::NonNegativeNumber);
    run->add_option("--runs", flags.runs, "independent runs averaged into the curve")->check(CLI::Range(1u, 1000u));
    run->add_option("--npcs", flags.npcs, "npc-arena: number of NPCs")->check(CLI::Range(1u, 64u));
    run->add_option("--out", flags.out, "output directory");
    run->add_option("--value-at", flags.valueAt, "also plot run 1's value function after these trials")
        ->delimiter(',');
    run->add_flag("--keep-going", flags.keepGoing, "cart-pole: keep learning after a trial reaches the cap");
    run->add_flag("!--no-save", flags.save, "do not save the trained agent");
    run->add_flag("--shared-brain", flags.sharedBrain, "npc-arena: all NPCs are bodies of one shared brain");
    CLI::App* compare = app.add_subcommand(
        "compare-brains", "npc-arena: NPCs with one brain each vs one shared brain, over fixed seeds, with a plot");
    BrainComparison comparison;
    compare->add_option("--seeds", comparison.seeds, "seeds 1..N, one run per mode each")->check(CLI::Range(1u, 100u));
    compare->add_option("--minutes", comparison.minutes, "simulated minutes per run")->check(CLI::Range(1u, 1000u));
    compare->add_option("--npcs", comparison.npcs, "NPCs in the arena")->check(CLI::Range(1u, 64u));
    compare->add_option("--out", comparison.out, "output directory");
    CLI::App* rays = app.add_subcommand(
        "ray-npc", "raycast NPCs: agents learning at library defaults vs scripted steering, per simulated minute");
    RayNpcComparison rayNpcs;
    std::string raySeeds = "1-5";
    rays->add_option("--seeds", raySeeds, "seeds: N (1..N), A-B or a list A,B,C");
    rays->add_option("--minutes", rayNpcs.minutes, "simulated minutes per run")->check(CLI::Range(1u, 1000u));
    rays->add_option("--npcs", rayNpcs.npcs, "NPCs in the arena")->check(CLI::Range(1u, 64u));
    rays->add_option("--rays", rayNpcs.rays, "rays per NPC (8-16; sensors beyond 16 need a library that takes them)")
        ->check(CLI::Range(8u, 16u));
    rays->add_flag("--shared-brain", rayNpcs.sharedBrain, "all NPCs are bodies of one shared brain");
    rays->add_option("--progress-reward", rayNpcs.progressReward,
                     "reward per metre an NPC closes on its target (0: arrival only; docs/scenes.md)")
        ->check(CLI::Range(0.0f, 100.0f));
    rays->add_option("--out", rayNpcs.out, "output directory");
    run->add_flag("--defaults", agent.libraryDefaults,
                  "every learning setting at the library's default: only the scene's sensors, actions and features");
    run->add_option("--set", agent.settings, "a setting by its C ABI name, e.g. tau_discount=2 (after --defaults)");
    run->add_option("--resolution", agent.resolution, "RBFs across each continuous sensor")->check(CLI::Range(1u, 1024u));
    run->add_option("--tau-value", agent.tauValue, "critic learning time constant (s)");
    run->add_option("--tau-discount", agent.tauDiscount, "discount time constant (s)");
    run->add_option("--tau-eligibility", agent.tauEligibility, "eligibility trace time constant (s)");
    run->add_option("--policy-multiplier", agent.policyMultiplier, "actor learning rate / critic learning rate");
    run->add_flag("--planning", agent.planning, "learn a predictive model and plan");
    run->add_option("--curiosity", agent.curiosity, "curiosity reward (turns planning on)")
        ->check(CLI::IsMember({"none", "novelty", "progress"}));
    CLI11_PARSE(app, argc, argv);

    try {
        if (*list) {
            listAll();
            return 0;
        }
        if (*compare) return compareBrains(comparison);
        if (*rays) {
            rayNpcs.seeds = parseSeeds(raySeeds);
            return compareRayNpcs(rayNpcs);
        }
        return runCommand(flags, agent);
    } catch (const verve::Error& e) {
        std::fprintf(stderr, "verve-demo: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "verve-demo: %s\n", e.what());
        return 1;
    }
}
