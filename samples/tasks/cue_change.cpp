#include "tasks/cue_change.hpp"

#include <numeric>
#include <stdexcept>
#include <utility>

#include "tasks/task_rng.hpp"

namespace verve::tasks {

CueChange::CueChange(std::uint64_t runSeed, const CueChangeConfig& config) : config_(config) {
    if (config.cues < 1 || config.actions < 2 || config.changedCues > config.cues) {
        throw std::invalid_argument("CueChange: needs >= 1 cue, >= 2 actions and changedCues <= cues");
    }
    TaskRng rng(runSeed);
    for (std::uint32_t c = 0; c < config.cues; ++c) before_.push_back(rng.below(config.actions));
    std::vector<std::uint32_t> order(config.cues);
    std::iota(order.begin(), order.end(), 0u);
    for (std::uint32_t i = config.cues - 1; i > 0; --i) std::swap(order[i], order[rng.below(i + 1)]);
    after_ = before_;
    for (std::uint32_t i = 0; i < config.changedCues; ++i) {
        // Any other action, uniformly: the old one shifted by 1..actions-1.
        std::uint32_t& a = after_[order[i]];
        a = (a + 1 + rng.below(config.actions - 1)) % config.actions;
    }
    settings_.addDiscreteSensor(config.cues);
    settings_.numActions = config.actions;
    // Settings for a world that changes (docs/algorithm.md, "A changing world"): bounded actor
    // weights, and an actor fast relative to a slower critic, so that a habit that stops paying
    // falls below the alternatives before the critic has adjusted to it.
    settings_.policyWeightBound = 10.0f;
    settings_.tauValue = 0.5f;
    settings_.policyMultiplier = 25.0f;
}

void CueChange::beginTrial(std::uint64_t seed) {
    ++trialsBegun_;
    cue_ = TaskRng(seed).below(config_.cues);
    correct_ = false;
}

void CueChange::observe(Observation& out) const { out.setDiscrete(0, static_cast<std::int32_t>(cue_)); }

StepResult CueChange::act(std::uint32_t action) {
    if (action >= config_.actions) throw std::invalid_argument("CueChange::act: no such action");
    correct_ = action == mapping()[cue_];
    return StepResult{correct_ ? 1.0f : -1.0f, true};
}

}  // namespace verve::tasks
