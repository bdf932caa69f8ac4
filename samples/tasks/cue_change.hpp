// A cue -> action task whose rules change (issue "agents that keep up with a changing world"): each
// trial shows one of `cues` cues (a discrete sensor), the agent answers with one of `actions`
// actions, and the trial ends at once with +1 for the cue's correct action, -1 otherwise. The
// mapping is drawn per run; from trial `changeTrial` on (counted on this instance), the first
// `changedCues` cues of a shuffled order move to another correct action. Success: correct answer.
// Agent settings: policy weight bound 10, tau_value 0.5 s, policy multiplier 25 (the library
// defaults relearn nothing: docs/experiments.md, "A changing world").
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "tasks/task.hpp"

namespace verve::tasks {

struct CueChangeConfig {
    std::uint32_t cues = 8;
    std::uint32_t actions = 5;
    std::uint32_t changeTrial = 1000;  // the rules change before this trial
    std::uint32_t changedCues = 4;
};

class CueChange final : public Task {
public:
    CueChange(std::uint64_t runSeed, const CueChangeConfig& config = {});  // throws std::invalid_argument

    std::string name() const override { return "cue-change"; }
    std::uint32_t maxStepsPerTrial() const override { return 1; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;
    bool succeeded() const override { return correct_; }
    std::uint32_t optimalSteps() const override { return 1; }

    std::uint32_t correctAction(std::uint32_t cue) const { return mapping()[cue]; }
    std::uint32_t cue() const { return cue_; }

private:
    const std::vector<std::uint32_t>& mapping() const { return trialsBegun_ > config_.changeTrial ? after_ : before_; }

    CueChangeConfig config_;
    std::vector<std::uint32_t> before_, after_;
    std::uint64_t trialsBegun_ = 0;
    std::uint32_t cue_ = 0;
    bool correct_ = false;
};

}  // namespace verve::tasks
