// The 10-armed bandit (thesis fig. 16): one state, ten levers. Each lever's mean is drawn once per
// run from N(0, 1); a pull pays N(mean, 1). The task is continuing, as the thesis's tau_disc 0.3 s
// implies (a discount only matters when pulls bootstrap from the next one): a trial is one pull of an
// unending stream, so the curve's reward is the mean payoff per pull. Payoffs are reported unclamped
// (comparable with the original's 1.48); the agent clamps every reward to [-1, 1] before learning.
// Agent settings (thesis): policy multiplier 100, tau_disc 0.3 s; no sensors.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "tasks/task.hpp"
#include "tasks/task_rng.hpp"

namespace verve::tasks {

class Bandit final : public Task {
public:
    explicit Bandit(std::uint64_t runSeed, std::uint32_t arms = 10);  // throws if arms < 2

    std::string name() const override { return "bandit"; }
    std::uint32_t maxStepsPerTrial() const override { return 1; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;

    // Success: the pull chose the lever with the highest mean.
    bool succeeded() const override { return lastAction_ == best_; }
    bool continuing() const override { return true; }
    float carriedReward() const override { return lastPayoff_; }

    const std::vector<double>& means() const { return means_; }
    std::uint32_t bestArm() const { return best_; }

private:
    std::vector<double> means_;
    std::uint32_t best_ = 0;
    std::uint32_t lastAction_ = 0xFFFFFFFFu;
    float lastPayoff_ = 0.0f;  // paid by the previous pull, delivered with the next update
    TaskRng noise_{0};
};

}  // namespace verve::tasks
