// Everything verve-demo can run, by name: the thesis's discrete tasks (samples/tasks registry) and
// the single-agent Bullet scenes (samples/scenes registry), with the one number per trial that
// shows learning. The NPC arena, a many-agent scene, is handled by arena_run.hpp.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tasks/driver.hpp"

namespace verve::demo {

struct Runnable {
    std::string name;
    std::string kind;  // "task" or "scene"
    std::string description;
    tasks::TaskFactory make;
    std::uint32_t trials;      // default trial count
    std::string metricLabel;   // y axis of the learning curve
    bool higherIsBetter;
    bool capMeansSolved;       // reaching the step cap is the goal (cart-pole): a run stops there
    std::vector<std::string> sensorNames;  // continuous sensors; empty: generic names
    std::function<double(const tasks::TrialResult&, const tasks::Environment&)> metric;
};

const std::vector<Runnable>& catalog();
const Runnable* findRunnable(const std::string& name);  // nullptr when unknown

}  // namespace verve::demo
