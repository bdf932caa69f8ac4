#include "arena_run.hpp"

#include <cstdio>

#include "progress.hpp"

namespace verve::demo {

ArenaOutcome runArena(std::uint32_t minutes, std::uint64_t seed, std::uint32_t npcs,
                      const tasks::DescriptorOverride& overrides, bool sharedBrain, bool batch) {
    scenes::NpcArenaConfig config;
    config.npcs = npcs;
    config.sharedBrain = sharedBrain;
    config.batch = batch;
    AgentDescriptor desc = scenes::NpcArena::defaultDescriptor();
    if (overrides) overrides(desc);
    ArenaOutcome outcome;
    outcome.arena = std::make_unique<scenes::NpcArena>(config, seed, desc);
    Progress progress(minutes);
    for (std::uint32_t m = 0; m < minutes; ++m) {
        const scenes::ArenaStats s = outcome.arena->run(60.0);
        outcome.foodPerNpcMinute.push_back(s.foodPerNpcMinute());
        outcome.hazardPercent.push_back(100.0 * s.hazardFraction());
        char text[160];
        std::snprintf(text, sizeof text, "minute | food per NPC-minute %.2f (first %.2f) | time in hazard %.1f%% (first %.1f%%)",
                      outcome.foodPerNpcMinute.back(), outcome.foodPerNpcMinute.front(),
                      outcome.hazardPercent.back(), outcome.hazardPercent.front());
        progress.update(m + 1, text);
    }
    progress.finish();
    outcome.wallSeconds = progress.elapsedSeconds();
    return outcome;
}

}  // namespace verve::demo
