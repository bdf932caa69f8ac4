// A teacher's praise and scolding (docs/teaching.md): a player clicks "good" or "bad" some time
// after the act they judge (people take 0.2-2 s to react), so a judgement cannot go to the latest
// step alone. The agent remembers what it did over the last kWindowSeconds (the state's features
// and the action, per update) and a judgement moves the actor's preference for each remembered act
// by rate * praise * activation: a feature's act counted once however many updates repeated it
// (the largest activation, as a replacing trace), so that a judgement weighs the same at 10 or 60
// updates a second. Acts the teacher did not mean share the credit, but they are as often praised
// as scolded and cancel out over many judgements, while the judged act's credit adds up (Knox and
// Stone's TAMER assigns credit over a window in the same way). Praise is not a reward: the critic
// never sees it, so the game's own rewards and values stay as they are. A judgement moves a weight
// only within +-kPraiseReach, so acts scolded often end alike at the floor instead of frozen in order.
//
// Continuous actions (core/continuous_praise.cpp): an act also keeps the natural gradient of what
// it played (its deviation from the mean, as the actor's trace gathers it), and a judgement moves
// each mean and spread weight along it: praise pulls the mean towards the values played, scolding
// pushes it away. Greedy acts played the mean, which praise then leaves where it is.
//
// Remembering costs a copy of the active features per update, so an agent starts remembering at its
// first judgement (praise 0 arms it without judging) and keeps doing so; the memory is not saved.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/action_branches.hpp"
#include "core/active_feature.hpp"
#include "core/habit_bound.hpp"
#include "core/weight_table.hpp"

namespace verve::core {

class TeacherMemory {
public:
    static constexpr double kWindowSeconds = 2.5;
    // Acts kept at most (at 60 updates a second the window holds 150); older ones are forgotten.
    static constexpr std::size_t kMaxActs = 1024;
    // The farthest a judgement moves an actor weight from 0 (credit(): a scolded habit floors there).
    // Measured with the cue task and the pets (docs/teaching.md): 3 and 6 cost the cue task at 0.2 s
    // (0.337, 0.739 right), 10 kept it (0.759) and ended the Godot pet's frozen policy.
    static constexpr float kPraiseReach = 10.0f;

    bool armed() const { return armed_; }
    void arm() { armed_ = true; }
    // Room for remember() with `features` active features and `continuousColumns` gradients (the
    // agent's continuous actions' columns, the same on every call): it then allocates nothing.
    void reserve(std::size_t features, std::uint32_t continuousColumns = 0);
    // The act chosen `dt` seconds after the previous one: `action` at the features `phi`, and the
    // continuous columns' gradients (nullptr: none, or 0s).
    void remember(float dt, std::uint32_t action, const std::vector<ActiveFeature>& phi,
                  const float* continuous = nullptr) noexcept;
    // Moves the remembered acts' preferences by rate * praise * activation (kept within `range`);
    // a combined action's, each branch's chosen neuron (core/action_branches.hpp); the continuous
    // columns (after the branches' columns) along their remembered gradients. Allocates its
    // scratch before changing any weight.
    void credit(WeightTable& w, float praise, float rate, const PolicyRange& range, const ActionBranches& branches);
    std::size_t acts() const { return acts_.size() - first_; }

private:
    struct Act {
        double time;
        std::uint32_t action;
        std::uint32_t begin;  // into pool_
        std::uint32_t count;
    };
    struct Credit {
        std::uint32_t feature;
        std::uint32_t action;
        float activation;
    };
    struct ContinuousCredit {
        std::uint32_t feature;
        std::uint32_t column;
        float activation;
        float gradient;
    };
    void forgetBefore(double time) noexcept;
    void compact() noexcept;
    // core/continuous_praise.cpp: the remembered acts' continuous credits into continuousScratch_
    // (may throw: called before any weight changes), then applied from column `firstColumn` on.
    void gatherContinuous();
    void creditContinuous(WeightTable& w, float praise, float rate, std::uint32_t firstColumn) noexcept;

    bool armed_ = false;
    double clock_ = 0.0;  // seconds of remembered updates
    std::vector<Act> acts_;  // acts_[first_..] are remembered, oldest first
    std::size_t first_ = 0;
    std::vector<ActiveFeature> pool_;  // their features; pool_[acts_[first_].begin..] in use
    std::vector<Credit> scratch_;
    std::uint32_t continuousColumns_ = 0;
    std::vector<float> gradients_;  // continuousColumns_ per act, parallel to acts_
    std::vector<ContinuousCredit> continuousScratch_;
};

}  // namespace verve::core
