// Small helpers shared by the scenes.
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "verve/brain.hpp"
#include "verve/error.hpp"

namespace verve::scenes {

constexpr double kPi = 3.14159265358979323846;
inline double radians(double degrees) { return degrees * kPi / 180.0; }

// A sensor reading mapped to [-1, 1] by its stated range (the agent clamps what lies beyond).
inline float toSensor(double value, double range) { return static_cast<float>(value / range); }

inline std::uint32_t stepsIn(double seconds, double step) {
    return static_cast<std::uint32_t>(std::lround(seconds / step));
}

// Bad actions are a caller bug: say which scene and what was allowed, change nothing.
inline void checkAction(const std::string& scene, std::uint32_t action, std::uint32_t numActions) {
    if (action >= numActions)
        throw Error(ErrorCode::InvalidArgument, scene + ": action " + std::to_string(action) +
                                                    " out of range (0.." +
                                                    std::to_string(numActions - 1) + ")");
}

// The next NPC's agent: its own, or (shared) a body of one brain made from the first NPC's
// descriptor; the bodies keep the brain alive.
inline void addNpcAgent(std::vector<Agent>& agents, std::unique_ptr<Brain>& brain, const AgentDescriptor& d, bool shared) {
    if (!shared) {
        agents.emplace_back(d);
        return;
    }
    if (!brain) brain = std::make_unique<Brain>(d);
    agents.push_back(brain->makeBody());
}

}  // namespace verve::scenes
