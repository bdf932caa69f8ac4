#include "tasks/sequential_actions.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "tasks/task_rng.hpp"

namespace verve::tasks {

SequentialActions::SequentialActions(std::uint64_t runSeed, std::uint32_t stimuli, std::uint32_t trialsPerBlock)
    : stimuli_(stimuli), trialsPerBlock_(trialsPerBlock) {
    if (stimuli < 2 || trialsPerBlock < 1) {
        throw std::invalid_argument("SequentialActions: needs >= 2 stimuli and >= 1 trial per block");
    }
    correct_.resize(stimuli);
    std::iota(correct_.begin(), correct_.end(), 0u);
    TaskRng rng(runSeed);
    for (std::uint32_t i = stimuli - 1; i > 0; --i) std::swap(correct_[i], correct_[rng.below(i + 1)]);

    settings_.addDiscreteSensor(stimuli);
    settings_.numActions = stimuli;
    settings_.policyMultiplier = 1000.0f;
    settings_.tauEligibility = 0.2f;
    settings_.tauDiscount = 5.0f;
    settings_.tauValue = 0.1f;
}

void SequentialActions::beginTrial(std::uint64_t /*seed: the schedule is deterministic*/) {
    const auto block = static_cast<std::uint32_t>(
        std::min<std::uint64_t>(trialsBegun_ / trialsPerBlock_, stimuli_ - 1));
    ++trialsBegun_;
    first_ = stimuli_ - 1 - block;
    current_ = first_;
    completed_ = false;
}

void SequentialActions::observe(Observation& out) const { out.setDiscrete(0, static_cast<std::int32_t>(current_)); }

StepResult SequentialActions::act(std::uint32_t action) {
    if (action >= stimuli_) throw std::invalid_argument("SequentialActions::act: no such action");
    if (action != correct_[current_]) return StepResult{0.0f, true};
    if (current_ + 1 == stimuli_) {
        completed_ = true;
        return StepResult{1.0f, true};
    }
    ++current_;
    return StepResult{0.0f, false};
}

}  // namespace verve::tasks
