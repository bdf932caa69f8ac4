// The Bullet scenes by name, for the runner, tests and benchmarks. Single-agent scenes are
// tasks::Environment factories; the NPC arena (many agents) is listed separately by the runner.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tasks/environment.hpp"

namespace verve::scenes {

enum class SceneMetric : std::uint8_t {
    RewardPerStep,    // mean reward per agent step (pendulum: +1 upright, -1 otherwise)
    BalanceSeconds,   // simulated seconds until failure or the cap (cart-pole)
};

struct SceneInfo {
    std::string name;
    std::string description;
    std::function<std::unique_ptr<tasks::Environment>()> make;
    std::uint32_t trials;  // a run long enough to show the thesis result
    SceneMetric metric;
    bool capMeansSolved;   // a trial that reaches maxStepsPerTrial is the goal: a run may stop there
    std::vector<std::string> sensorNames;  // continuous sensors, for plot axes
};

const std::vector<SceneInfo>& sceneRegistry();
const SceneInfo* findScene(const std::string& name);  // nullptr when unknown

// The NPC arena runs many agents at once, so it is not an Environment; its name for the runner.
inline const char* kNpcArenaName = "npc-arena";

}  // namespace verve::scenes
