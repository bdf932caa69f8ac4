// The base of the thesis's discrete tasks: an Environment that also knows its own optimum, so
// experiments can report how far learning is from perfect, and whose agent settings a registry
// variant may adjust (e.g. the same maze with planning on).
#pragma once
#include <cstdint>

#include "tasks/environment.hpp"

namespace verve::tasks {

// How a task presents grid positions: one discrete sensor per axis (a value per cell), or one
// continuous sensor per axis where cell i of n reads -1 + i * 2 / (n - 1).
enum class Sensors : std::uint8_t { Discrete, Continuous };

float cellToSensor(int cell, int cells);

class Task : public Environment {
public:
    AgentDescriptor agentDescriptor() const override { return settings_; }
    // The defaults agentDescriptor() returns; registry variants change them after construction.
    AgentDescriptor& settings() { return settings_; }

    // Fewest steps that could end the current trial; 0 when the task has no goal to reach.
    virtual std::uint32_t optimalSteps() const { return 0; }
    // Whether the trial just played counts as a success (task-specific; see each task).
    virtual bool succeeded() const { return false; }
    // True when beginTrial placed the agent where the trial is already over (a hot plate start
    // inside a safe zone): such a trial takes 0 steps and the agent is not consulted.
    virtual bool finishedAtStart() const { return false; }
    // A continuing task never ends: its trials are slices of one stream of steps. The agent keeps
    // its short-term memory across trials, and the reward of a slice's last step reaches it with the
    // next slice's first update (carriedReward), so nothing is learned as if the stream had ended.
    virtual bool continuing() const { return false; }
    virtual float carriedReward() const { return 0.0f; }
    // How a trial cut off at the step cap ends: Agent::truncateEpisode (true, the default), or, for
    // a task that keeps the original library's protocol, Agent::resetShortTermMemory.
    virtual bool truncatesAtCap() const { return true; }

protected:
    // The thesis's settings, as its experiments ran: nothing adapts (AgentDescriptor::adaptation 0).
    // The defaults table runs the same tasks with every setting at the library's defaults.
    Task() { settings_.adaptation = 0; }

    AgentDescriptor settings_;
};

}  // namespace verve::tasks
