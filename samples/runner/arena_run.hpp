// The learning-NPC arena for the demo: each "trial" is one simulated minute of every NPC learning.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "npc_arena.hpp"
#include "tasks/driver.hpp"

namespace verve::demo {

struct ArenaOutcome {
    std::vector<double> foodPerNpcMinute;  // per minute
    std::vector<double> hazardPercent;     // share of NPC time spent in the hazard, per minute
    std::unique_ptr<scenes::NpcArena> arena;
    double wallSeconds = 0.0;
};

// sharedBrain: the NPCs are bodies of one brain instead of separate agents.
ArenaOutcome runArena(std::uint32_t minutes, std::uint64_t seed, std::uint32_t npcs,
                      const tasks::DescriptorOverride& overrides, bool sharedBrain = false, bool batch = false);

}  // namespace verve::demo
