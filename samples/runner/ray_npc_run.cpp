#include "ray_npc_run.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "plots.hpp"
#include "progress.hpp"
#include "ray_npc.hpp"

namespace verve::demo {

namespace {

using scenes::RayNpcScene;
using scenes::RayNpcStats;

std::uint64_t parseSeed(const std::string& text) {
    std::size_t used = 0;
    const unsigned long long v = text.empty() || text[0] == '-' ? 0 : std::stoull(text, &used);
    if (used != text.size() || text.empty()) throw std::invalid_argument("not a seed: '" + text + "'");
    return v;
}

std::vector<RayNpcStats> runMinutes(const RayNpcComparison& c, std::uint64_t seed, RayNpcScene::Driver driver) {
    scenes::RayNpcConfig config;
    config.npcs = c.npcs;
    config.rays = c.rays;
    config.sharedBrain = c.sharedBrain;
    config.progressReward = c.progressReward;
    // Library defaults: the scene's sensors and actions, nothing tuned (RayNpcScene::defaultDescriptor).
    RayNpcScene scene(config, seed);
    scene.setDriver(driver);
    const bool script = driver == RayNpcScene::Driver::Script;
    std::printf("ray-npc, %u NPCs, %u rays, %s, seed %llu:\n", c.npcs, c.rays,
                script ? "scripted steering" : c.sharedBrain ? "one shared brain learning" : "agents learning",
                static_cast<unsigned long long>(seed));
    Progress progress(c.minutes, 5);
    std::vector<RayNpcStats> minutes;
    for (std::uint32_t m = 0; m < c.minutes; ++m) {
        minutes.push_back(scene.run(60.0));
        const RayNpcStats& s = minutes.back();
        char text[200];
        std::snprintf(text, sizeof text,
                      "minute | targets per NPC-minute %.2f | hazard %.1f%% | collisions per NPC-minute %.2f | reward %.2f",
                      s.targetsPerNpcMinute(), 100 * s.hazardFraction(), s.collisionsPerNpcMinute(),
                      s.rewardPerNpcMinute());
        progress.update(m + 1, text);
    }
    progress.finish();
    return minutes;
}

struct Mean {
    double targets = 0, hazardPercent = 0, collisions = 0, reward = 0;
};

Mean meanOver(const std::vector<std::vector<RayNpcStats>>& runs, std::size_t minute) {
    Mean m;
    const double n = static_cast<double>(runs.size());
    for (const auto& run : runs) {
        m.targets += run[minute].targetsPerNpcMinute() / n;
        m.hazardPercent += 100 * run[minute].hazardFraction() / n;
        m.collisions += run[minute].collisionsPerNpcMinute() / n;
        m.reward += run[minute].rewardPerNpcMinute() / n;
    }
    return m;
}

void writeRow(std::ofstream& csv, std::uint64_t seed, std::size_t minute, const char* driver, const RayNpcStats& s) {
    csv << seed << ',' << minute + 1 << ',' << driver << ',' << s.targetsPerNpcMinute() << ','
        << 100 * s.hazardFraction() << ',' << s.collisionsPerNpcMinute() << ',' << s.rewardPerNpcMinute() << '\n';
}

}  // namespace

std::vector<std::uint64_t> parseSeeds(const std::string& text) {
    std::vector<std::uint64_t> seeds;
    const std::size_t dash = text.find('-');
    if (text.find(',') != std::string::npos) {
        std::size_t start = 0;
        for (;;) {
            const std::size_t comma = text.find(',', start);
            seeds.push_back(parseSeed(text.substr(start, comma - start)));
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    } else if (dash != std::string::npos) {
        const std::uint64_t first = parseSeed(text.substr(0, dash)), last = parseSeed(text.substr(dash + 1));
        if (last < first || last - first >= 1000) throw std::invalid_argument("a seed range is first-last, at most 1000 seeds");
        for (std::uint64_t s = first; s <= last; ++s) seeds.push_back(s);
    } else {
        const std::uint64_t count = parseSeed(text);
        if (count == 0 || count > 1000) throw std::invalid_argument("a seed count is 1 to 1000");
        for (std::uint64_t s = 1; s <= count; ++s) seeds.push_back(s);
    }
    return seeds;
}

int compareRayNpcs(const RayNpcComparison& c) {
    std::filesystem::create_directories(c.out);
    std::vector<std::vector<RayNpcStats>> script, agents;
    for (std::uint64_t seed : c.seeds) {
        script.push_back(runMinutes(c, seed, RayNpcScene::Driver::Script));
        agents.push_back(runMinutes(c, seed, RayNpcScene::Driver::Agents));
    }

    const std::string base = (std::filesystem::path(c.out) / "ray-npc").string();
    std::ofstream runs(base + "-runs.csv");
    runs << "seed,minute,driver,targets_per_npc_minute,hazard_percent,collisions_per_npc_minute,reward_per_npc_minute\n";
    for (std::size_t s = 0; s < c.seeds.size(); ++s)
        for (std::size_t m = 0; m < c.minutes; ++m) {
            writeRow(runs, c.seeds[s], m, "script", script[s][m]);
            writeRow(runs, c.seeds[s], m, "agents", agents[s][m]);
        }
    if (!runs) throw std::runtime_error("cannot write " + base + "-runs.csv");

    std::printf("\nper simulated minute, mean of %zu seeds (reward per NPC-minute: +1 a target, -1 a step in the "
                "hazard, -0.1 a step touching a wall or box", c.seeds.size());
    if (c.progressReward > 0) std::printf(", %g per metre closed on the target", static_cast<double>(c.progressReward));
    std::printf(")\n");
    std::printf("minute | agents: targets hazard%% collisions reward | script: targets hazard%% collisions reward\n");
    std::ofstream curve(base + "-curve.csv"), reward(base + "-reward.csv");
    curve << "minute,agents_targets,script_targets,agents_hazard_percent,script_hazard_percent,"
             "agents_collisions,script_collisions,agents_reward,script_reward\n";
    reward << "minute,agents,script\n";
    for (std::size_t m = 0; m < c.minutes; ++m) {
        const Mean a = meanOver(agents, m), s = meanOver(script, m);
        std::printf("%6zu | %14.2f %6.1f %10.2f %7.2f | %14.2f %6.1f %10.2f %7.2f\n", m + 1, a.targets, a.hazardPercent,
                    a.collisions, a.reward, s.targets, s.hazardPercent, s.collisions, s.reward);
        curve << m + 1 << ',' << a.targets << ',' << s.targets << ',' << a.hazardPercent << ',' << s.hazardPercent
              << ',' << a.collisions << ',' << s.collisions << ',' << a.reward << ',' << s.reward << '\n';
        reward << m + 1 << ',' << a.reward << ',' << s.reward << '\n';
    }
    if (!curve || !reward) throw std::runtime_error("cannot write " + base + "-curve.csv");
    curve.close();
    reward.close();

    // The bar the learning test states: a minute in which the agents out-earn the script's mean.
    std::printf("\nper seed: reward per NPC-minute, the script's mean, and the first minute the agents beat it\n");
    for (std::size_t s = 0; s < c.seeds.size(); ++s) {
        double scriptMean = 0, scriptTargets = 0;
        for (const RayNpcStats& st : script[s]) {
            scriptMean += st.rewardPerNpcMinute() / c.minutes;
            scriptTargets += st.targetsPerNpcMinute() / c.minutes;
        }
        std::size_t beat = 0;
        for (std::size_t m = 0; m < c.minutes && beat == 0; ++m)
            if (agents[s][m].rewardPerNpcMinute() > scriptMean) beat = m + 1;
        std::printf("  seed %llu: script %.2f, agents %.2f (minute 1) -> %.2f (minute %u); %s; targets: script %.2f, "
                    "agents %.2f in minute %u\n",
                    static_cast<unsigned long long>(c.seeds[s]), scriptMean, agents[s].front().rewardPerNpcMinute(),
                    agents[s].back().rewardPerNpcMinute(), c.minutes,
                    beat > 0 ? ("beaten in minute " + std::to_string(beat)).c_str() : "not beaten", scriptTargets,
                    agents[s].back().targetsPerNpcMinute(), c.minutes);
    }
    std::printf("  runs:   %s-runs.csv\n  curve:  %s-curve.csv\n", base.c_str(), base.c_str());
    if (plotColumns(base + "-reward.csv", base + "-reward.png",
                    std::to_string(c.npcs) + " raycast NPCs: learning at defaults vs scripted steering (mean of " +
                        std::to_string(c.seeds.size()) + " seeds)",
                    "simulated minute", "reward per NPC-minute", {"agents learning", "scripted steering"}))
        std::printf("  plot:   %s-reward.png\n", base.c_str());
    return 0;
}

}  // namespace verve::demo
