// Full-size planning measurements for docs/planning.md (not a test): runs a registry task with
// descriptor overrides given as key=value and prints the windows the docs quote.
//   planning_measure maze2-planning runs=10 trials=51 accumulate=1 real=1 ordinal=0 cap=50
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tasks/registry.hpp"

using namespace verve;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s task [runs=N trials=N seed=N key=value...]\n", argv[0]);
        return 2;
    }
    const tasks::TaskInfo* info = tasks::findTask(argv[1]);
    if (info == nullptr) return 2;
    std::uint32_t runs = info->runs, trials = info->trials;
    std::uint64_t seed = 1;
    std::vector<std::pair<std::string, float>> settings;
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto eq = arg.find('=');
        if (eq == std::string::npos) return 2;
        const std::string key = arg.substr(0, eq);
        const float value = std::strtof(arg.c_str() + eq + 1, nullptr);
        if (key == "runs") runs = static_cast<std::uint32_t>(value);
        else if (key == "trials") trials = static_cast<std::uint32_t>(value);
        else if (key == "seed") seed = static_cast<std::uint64_t>(value);
        else settings.emplace_back(key, value);
    }
    auto overrides = [&](AgentDescriptor& d) {
        for (const auto& [key, v] : settings) {
            if (key == "planning") d.planning = v != 0.0f;
            else if (key == "accumulate") d.planningAccumulatesUncertainty = v != 0.0f;
            else if (key == "real") d.learnFromRealSteps = v != 0.0f;
            else if (key == "ordinal") d.discretePrediction = v != 0.0f ? DiscretePrediction::Ordinal : DiscretePrediction::Categorical;
            else if (key == "cap") d.maxPlanningSteps = static_cast<std::uint32_t>(v);
            else if (key == "threshold") d.planningUncertaintyThreshold = v;
            else if (key == "curiosity") d.curiosity = static_cast<CuriosityMode>(static_cast<int>(v));
            else if (key == "factor") d.curiosityFactor = v;
            else if (key == "tauModel") d.tauModel = v;
            else if (key == "multiplier") d.policyMultiplier = v;
            else if (key == "tauDiscount") d.tauDiscount = v;
            else if (key == "bound") d.policyWeightBound = v;
            else if (key == "tauValue") d.tauValue = v;
            else if (key == "tauEligibility") d.tauEligibility = v;
            else if (key == "resolution") d.resolution = static_cast<std::uint32_t>(v);
            else std::fprintf(stderr, "unknown key %s\n", key.c_str());
        }
    };
    const tasks::LearningCurve c = tasks::runExperiment(info->make, runs, trials, seed, overrides, 2);
    const auto& curve = info->metric == tasks::Metric::Steps ? c.steps : c.reward;
    const std::size_t n = c.trials();
    std::printf("%s runs=%u trials=%zu first10=%.1f", info->name.c_str(), runs, n, tasks::windowMean(curve, 0, 10));
    if (n > 50) std::printf(" 41-50=%.1f", tasks::windowMean(curve, 41, 51));
    if (n > 61) std::printf(" 61-80=%.1f", tasks::windowMean(curve, 61, 81));
    std::printf(" last10=%.3f success(last10)=%.3f\n", tasks::windowMean(curve, n - 10, n),
                tasks::windowMean(c.success, n - 10, n));
    return 0;
}
