// A noisy-TV room (Schmidhuber's example, thesis chapter 2): a 6x6 open grid whose bottom-right
// 2x2 corner holds a screen of pure noise. A third discrete sensor reads the screen: a random
// value 1-4 while the agent stands in the corner, 0 elsewhere. No rewards, no terminal state,
// 100 steps per trial. A novelty-curious agent keeps returning to the unpredictable screen; a
// learning-progress agent, whose errors there never fall, does not.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>

#include "tasks/grid.hpp"
#include "tasks/task.hpp"
#include "tasks/task_rng.hpp"

namespace verve::tasks {

class NoisyTv final : public Task {
public:
    NoisyTv() {
        grid_.addPositionSensors(settings_, Sensors::Discrete);
        settings_.addDiscreteSensor(5);  // the screen: 0 off, 1-4 noise
        settings_.numActions = 5;
        settings_.policyMultiplier = 2.0f;
        settings_.planning = true;
        settings_.tauModel = 0.0f;
        settings_.maxPlanningSteps = 50;
    }

    std::string name() const override { return "noisy-tv"; }
    std::uint32_t maxStepsPerTrial() const override { return 100; }
    void beginTrial(std::uint64_t seed) override {
        position_ = Cell{0, 0};
        rng_ = TaskRng(seed);
        screen_ = 0;
    }
    void observe(Observation& out) const override {
        grid_.writePosition(position_, Sensors::Discrete, out);
        out.setDiscrete(2, screen_);
    }
    StepResult act(std::uint32_t action) override {
        if (action >= 5) throw std::invalid_argument("NoisyTv::act: no such action");
        position_ = grid_.move(position_, static_cast<Move>(action));
        const bool watching = position_.x >= 4 && position_.y >= 4;
        screen_ = watching ? static_cast<std::int32_t>(1 + rng_.below(4)) : 0;
        if (watching) ++stepsWatching_;
        return StepResult{0.0f, false};
    }

    // Steps that ended in front of the screen since the last reset of the counter.
    std::uint32_t takeStepsWatching() {
        const std::uint32_t n = stepsWatching_;
        stepsWatching_ = 0;
        return n;
    }

private:
    Grid grid_{6, 6};
    Cell position_{0, 0};
    TaskRng rng_{1};
    std::int32_t screen_ = 0;
    std::uint32_t stepsWatching_ = 0;
};

}  // namespace verve::tasks
