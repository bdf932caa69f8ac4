// The raycast NPC scene (samples/scenes/ray_npc.hpp) for the demo: NPCs learning at the library's
// defaults against the designer's scripted steering, on the same seeds, per simulated minute.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace verve::demo {

struct RayNpcComparison {
    std::vector<std::uint64_t> seeds{1, 2, 3, 4, 5};
    std::uint32_t minutes = 10;  // simulated minutes per run
    std::uint32_t npcs = 4;
    std::uint32_t rays = 8;
    bool sharedBrain = false;
    float progressReward = 0.0f;  // per metre closed on the target (scenes::RayNpcConfig)
    std::string out = "demo-out";
};

// "5" is seeds 1..5 (as compare-brains counts them), "3-7" a range, "1,4,9" a list. Throws
// std::invalid_argument on anything else.
std::vector<std::uint64_t> parseSeeds(const std::string& text);

// Runs every seed twice (script, then agents learning), prints both per minute, writes
// <out>/ray-npc-runs.csv (seed, minute, driver and the four stats), <out>/ray-npc-curve.csv (the
// means over seeds per minute) and a PNG of the reward. Returns the exit code.
int compareRayNpcs(const RayNpcComparison& settings);

}  // namespace verve::demo
