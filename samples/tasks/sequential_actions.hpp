// Sequential action learning (thesis fig. 17, after Suri & Schultz 1998). Seven stimuli, seven
// actions; each stimulus has one correct action (a random permutation drawn once per run, so no
// action index is favoured). A correct action presents the next stimulus; the correct action on
// the last stimulus pays 1 and ends the trial; a wrong action ends the trial with 0 (our reading:
// the thesis only says reinforcement is 0 except after the final correct action).
// Training runs backwards in blocks of 100 trials: block b starts at stimulus 6 - b, so the last
// block (trials 600-699) needs all seven actions right. The block follows the count of trials
// begun on this instance. Success: the trial was completed (reward 1).
// Agent settings (thesis): policy multiplier 1000, tau_elig 0.2 s, tau_disc 5 s.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "tasks/task.hpp"

namespace verve::tasks {

class SequentialActions final : public Task {
public:
    SequentialActions(std::uint64_t runSeed, std::uint32_t stimuli = 7, std::uint32_t trialsPerBlock = 100);

    std::string name() const override { return "sequential-actions"; }
    std::uint32_t maxStepsPerTrial() const override { return stimuli_; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;
    bool succeeded() const override { return completed_; }
    std::uint32_t optimalSteps() const override { return stimuli_ - first_; }

    std::uint32_t trialsPerBlock() const { return trialsPerBlock_; }
    std::uint32_t blocks() const { return stimuli_; }
    std::uint32_t firstStimulus() const { return first_; }
    std::uint32_t stimulus() const { return current_; }
    std::uint32_t correctAction(std::uint32_t stimulus) const { return correct_.at(stimulus); }

private:
    std::uint32_t stimuli_;
    std::uint32_t trialsPerBlock_;
    std::vector<std::uint32_t> correct_;
    std::uint64_t trialsBegun_ = 0;
    std::uint32_t first_ = 0;
    std::uint32_t current_ = 0;
    bool completed_ = false;
};

}  // namespace verve::tasks
