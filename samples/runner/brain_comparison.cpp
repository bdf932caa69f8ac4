#include "brain_comparison.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "arena_run.hpp"
#include "plots.hpp"

namespace verve::demo {

int compareBrains(const BrainComparison& c) {
    std::filesystem::create_directories(c.out);
    // curves[mode][seed][minute]: food per NPC-minute; mode 0 separate brains, 1 one shared brain
    // (single updates), 2 one shared brain stepped by a batch (its bodies in phases, docs/crowds.md).
    constexpr int kModes = 3;
    const char* const names[kModes] = {"one brain each", "one shared brain", "one shared brain, batch"};
    const char* const columns[kModes] = {"separate", "shared", "shared_batch"};
    std::vector<std::vector<std::vector<double>>> curves(kModes);
    for (int mode = 0; mode < kModes; ++mode) {
        for (std::uint32_t seed = 1; seed <= c.seeds; ++seed) {
            std::printf("npc-arena, %u NPCs, %s, seed %u:\n", c.npcs, names[mode], seed);
            curves[mode].push_back(runArena(c.minutes, seed, c.npcs, nullptr, mode >= 1, mode == 2).foodPerNpcMinute);
        }
    }
    const std::string base = (std::filesystem::path(c.out) / "npc-arena-brains").string();
    std::ofstream csv(base + ".csv");
    csv << "minute,separate_brains,one_shared_brain,one_shared_brain_batch";
    for (int mode = 0; mode < kModes; ++mode)
        for (std::uint32_t seed = 1; seed <= c.seeds; ++seed) csv << ',' << columns[mode] << "_seed" << seed;
    csv << '\n';
    double totals[kModes] = {0.0, 0.0, 0.0};
    for (std::uint32_t m = 0; m < c.minutes; ++m) {
        csv << m + 1;
        for (int mode = 0; mode < kModes; ++mode) {
            double sum = 0.0;
            for (const auto& run : curves[mode]) sum += run[m];
            csv << ',' << sum / c.seeds;
            totals[mode] += sum / c.seeds;
        }
        for (int mode = 0; mode < kModes; ++mode)
            for (const auto& run : curves[mode]) csv << ',' << run[m];
        csv << '\n';
    }
    if (!csv) throw std::runtime_error("cannot write " + base + ".csv");
    csv.close();
    std::printf("food per NPC-minute over %u minutes, mean of %u seeds: one brain each %.3f, one shared brain %.3f, "
                "one shared brain in a batch %.3f\n",
                c.minutes, c.seeds, totals[0] / c.minutes, totals[1] / c.minutes, totals[2] / c.minutes);
    std::printf("  curves: %s.csv\n", base.c_str());
    if (plotColumns(base + ".csv", base + ".png",
                    std::to_string(c.npcs) + " NPCs learning: one brain each vs one shared brain (mean of " +
                        std::to_string(c.seeds) + " seeds)",
                    "simulated minute", "food per NPC per minute", {names[0], names[1], names[2]}))
        std::printf("  plot:   %s.png\n", base.c_str());
    return 0;
}

}  // namespace verve::demo
