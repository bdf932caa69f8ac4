#include "tasks/bandit.hpp"

#include <stdexcept>

namespace verve::tasks {

Bandit::Bandit(std::uint64_t runSeed, std::uint32_t arms) {
    if (arms < 2) throw std::invalid_argument("Bandit: needs at least 2 arms");
    TaskRng rng(runSeed);
    means_.resize(arms);
    for (std::uint32_t a = 0; a < arms; ++a) {
        means_[a] = rng.normal();
        if (means_[a] > means_[best_]) best_ = a;
    }
    settings_.numActions = arms;
    settings_.policyMultiplier = 100.0f;
    settings_.tauDiscount = 0.3f;
    settings_.tauValue = 0.1f;
}

void Bandit::beginTrial(std::uint64_t seed) {
    noise_ = TaskRng(seed);
    lastAction_ = 0xFFFFFFFFu;
}

void Bandit::observe(Observation& /*out: there are no sensors*/) const {}

StepResult Bandit::act(std::uint32_t action) {
    if (action >= means_.size()) throw std::invalid_argument("Bandit::act: no such lever");
    lastAction_ = action;
    lastPayoff_ = static_cast<float>(means_[action] + noise_.normal());
    return StepResult{lastPayoff_, false};
}

}  // namespace verve::tasks
