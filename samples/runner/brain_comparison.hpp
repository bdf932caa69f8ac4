// One brain for many bodies against one brain each, in the NPC arena: the same seeds (the same
// starts and food draws), NPCs as separate agents or as bodies of one shared brain.
#pragma once
#include <cstdint>
#include <string>

namespace verve::demo {

struct BrainComparison {
    std::uint32_t seeds = 5;    // seeds 1..seeds, each run once per mode
    std::uint32_t minutes = 10; // simulated minutes per run
    std::uint32_t npcs = 8;
    std::string out = "demo-out";
};

// Writes <out>/npc-arena-brains.csv (per minute: food per NPC-minute, mean over the seeds, for
// both modes, then every run) and its PNG; prints the per-mode means. Returns the exit code.
int compareBrains(const BrainComparison& settings);

}  // namespace verve::demo
