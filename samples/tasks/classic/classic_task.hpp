// Gymnasium's classic control tasks with their exact equations, rewards, termination and time
// limits: the yardstick Verve shares with the rest of the field (docs/experiments.md, "Classic
// control at defaults"). Each task describes only what a game programmer would: its sensors
// scaled into [-1, 1] by the ranges Gymnasium documents, its actions, dt and its reward; every
// learning setting is the library's default.
#pragma once
#include <cstdint>
#include <string>

#include "tasks/environment.hpp"
#include "tasks/task_rng.hpp"

namespace verve::tasks {

class ClassicTask : public Environment {
public:
    AgentDescriptor agentDescriptor() const override { return descriptor_; }
    std::uint32_t maxStepsPerTrial() const override { return timeLimit_; }
    float agentStep() const override { return dt_; }

    // Gymnasium's reward for the step just taken: what a return sums. act() hands the agent the
    // same reward, scaled into [-1, 1] where Gymnasium's is larger (Pendulum-v1).
    double gymnasiumReward() const { return gymnasiumReward_; }
    // The mean return over 100 episodes that counts as solved, and the training budget (steps) of
    // RL Baselines3 Zoo's tuned agent for the task.
    virtual double solvedReturn() const = 0;
    virtual std::uint64_t zooBudget() const = 0;
    virtual const char* zooAgent() const = 0;

protected:
    ClassicTask(std::uint32_t timeLimit, float dt) : timeLimit_(timeLimit), dt_(dt) {}

    AgentDescriptor descriptor_;
    double gymnasiumReward_ = 0.0;
    TaskRng rng_{0};

private:
    std::uint32_t timeLimit_;
    float dt_;
};

// Gymnasium's angle_normalize: into [-pi, pi).
double wrapAngle(double radians);

}  // namespace verve::tasks
