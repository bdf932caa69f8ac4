// TD(lambda) actor-critic on linear networks (thesis chapter 4, "Temporal Difference Learning").
//
// Critic: V(s) = sum_i w_i phi_i. Actor: one sigmoid neuron per action, y_a = 1 / (1 + e^-(sum_i w_ai phi_i)),
// chosen by roulette in proportion to y_a (with action branches, one roulette per branch over its
// own neurons: core/action_branches.hpp). Both learn w += eta * delta * e. Traces are replacing
// (e = max(e, phi); the actor's only for the chosen action of each branch) and decay by gamma * lambda. Traces are
// stored per feature, and a live list names the features whose trace is above the threshold, so
// work follows live traces, not the feature count. A feature's value trace is never below its
// policy traces (both take the max with the same phi and decay alike), so it alone decides liveness.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/action_branches.hpp"
#include "core/habit_bound.hpp"
#include "core/kernels.hpp"
#include "core/rng.hpp"
#include "core/state_representation.hpp"
#include "core/weight_table.hpp"

namespace verve::core {

struct TdRates {
    float value = 0.0f;   // eta_value
    float policy = 0.0f;  // eta_policy = k * eta_value
    PolicyRange policyRange;  // every actor weight stays within it (core/habit_bound.hpp)
};

// The real rewards an agent has learned from, widened to include 0 (a trial may end before any
// reward): [low, high] those of steps (update, truncateEpisode), [finalLow, finalHigh] those that
// ended a trial (endEpisode). They bound what any policy can earn: a return of step rewards within
// [low, high] that may end with one final reward within [finalLow, finalHigh] lies within
// [min(low / (1 - gamma), finalLow), max(high / (1 - gamma), finalHigh)] (a weighted mean of the two
// ends: gamma^n of the final one). A goal's +1 that ends the trial counts once, not for ever.
struct RewardRange {
    float low = 0.0f;
    float high = 0.0f;
    float finalLow = 0.0f;
    float finalHigh = 0.0f;
    void see(float reward) {
        low = std::min(low, reward);
        high = std::max(high, reward);
    }
    void seeFinal(float reward) {
        finalLow = std::min(finalLow, reward);
        finalHigh = std::max(finalHigh, reward);
    }
    float anyLow() const { return std::min(low, finalLow); }
    float anyHigh() const { return std::max(high, finalHigh); }
};

struct ValueBounds {
    float low = 0.0f;
    float high = 0.0f;
};

// Unnormalised RBFs extrapolate (their activations add up to more between trained points than at a
// border), and imagined steps add their own errors: a value beyond what any policy can earn must
// not bootstrap a TD error. Next to a wall an impossible value punished moving away until an agent
// stayed stuck there for good; with planning, imagined steps pushed a value to +13.7 in a task whose
// every real reward was -1 (docs/algorithm.md). Curiosity adds [bonusLow, bonusHigh] to a reward.
inline float discountedForever(float reward, float gamma) {
    if (reward == 0.0f) return 0.0f;
    return gamma < 1.0f ? reward / (1.0f - gamma) : std::copysign(std::numeric_limits<float>::infinity(), reward);
}
inline ValueBounds valueBounds(RewardRange rewards, float bonusLow, float bonusHigh, float gamma) {
    return ValueBounds{std::min(discountedForever(rewards.low + bonusLow, gamma), rewards.finalLow + bonusLow),
                       std::max(discountedForever(rewards.high + bonusHigh, gamma), rewards.finalHigh + bonusHigh)};
}
inline float bounded(float value, ValueBounds b) { return std::clamp(value, b.low, b.high); }

// Where a learning agent gives up on its policy: a state valued within 1e-4 of the way to the floor
// b.low < 0, the worst any policy can do: the worst step reward for ever (then no end is expected
// within ~9 discount time constants, e^-9.2 = 1e-4), or the worst final reward now. Nothing there is
// learned any more: every TD error of a step that stays at the floor is 0, so an actor saturated on
// a loop (pushing into a wall) kept it for good while states that lead out went untried
// (docs/algorithm.md, "A changing world: hopeless states explore"). Such a state chooses uniformly;
// -infinity when the rewards allow no floor below 0.
inline float hopelessValue(ValueBounds b) {
    return b.low < 0.0f ? b.low * (1.0f - 1e-4f) : -std::numeric_limits<float>::infinity();
}

// An actor neuron's activation y = 1 / (1 + e^-x) for its preference x (finite for any finite x).
inline float sigmoid(float x) { return 1.0f / (1.0f + std::exp(-x)); }

// An action mask's test: `allowed` holds numActions flags, or is nullptr for every action allowed.
inline bool actionAllowed(const std::uint8_t* allowed, std::uint32_t a) { return allowed == nullptr || allowed[a] != 0; }

class TdLearner {
public:
    static constexpr float kStepLimit = 1e12f;  // trainAndDecay's clamp on a weight's step (traces <= 1)
    // `continuousColumns`: the continuous actions' columns after the discrete ones
    // (core/continuous_actions.hpp), 0 without.
    TdLearner(const ActionBranches& branches, std::uint32_t continuousColumns, float traceThreshold);

    // `ahead`, in these three: a batch's next agent, asked for as the kernels go (prefetch.hpp).
    float value(const WeightTable& w, const std::vector<ActiveFeature>& phi, PrefetchQueue* ahead = nullptr) const;
    // Roulette choice over the sigmoid action activations y_a (left in `activations`); one pass
    // over the features also yields V(s) into `value`. `allowed` (one flag per actor column, or
    // nullptr for all) zeroes the activation of every action not allowed, so it is never chosen;
    // `greedy` takes the largest preference (the lowest index on ties) and draws no random number;
    // otherwise a state whose V(s) is at or below `uniformAtOrBelow` chooses uniformly among the
    // allowed actions. If every allowed y_a underflows, `activations` holds e^(x_a - max x) instead
    // (their limit). With branches, each branch chooses so in turn; the result is the combined action.
    std::uint32_t chooseAction(const WeightTable& w, const std::vector<ActiveFeature>& phi, Rng& rng,
                               std::vector<float>& activations, float& value,
                               const std::uint8_t* allowed = nullptr, bool greedy = false,
                               float uniformAtOrBelow = -std::numeric_limits<float>::infinity(),
                               PrefetchQueue* ahead = nullptr) const;

    // chooseAction's choice from the sums it made: `activations` holds [V(s), x_a...] (stride values).
    std::uint32_t chooseFromSums(Rng& rng, std::vector<float>& activations, float& value, const std::uint8_t* allowed,
                                 bool greedy, float uniformAtOrBelow) const;

    // w += eta * delta * e over the live traces, then e *= decay; traces whose every component
    // falls below the threshold are dropped. One pass: both follow the live list.
    void trainAndDecay(WeightTable& w, float delta, TdRates rates, float decay, PrefetchQueue* ahead = nullptr);
    // Staged training (td_staged.cpp), for a batch that updates the bodies of one brain on several
    // threads (core/shared_step.cpp). stage() keeps the step trainAndDecay would take and touches
    // nothing else (chooseActionStaged reads it); keepAndDecay() then keeps a copy of every live
    // trace, sorted into `parts` parts of the features (reserveStaged first), and decays the traces
    // as trainAndDecay would, in one pass, so the body can mark its new ones at once. trainPart(w, p)
    // adds the kept changes to part p's features only, so the parts of many bodies can train one
    // brain's weights at once on different threads, each weight taking the bodies' changes in body
    // order.
    void reserveStaged(std::uint32_t parts);
    void stage(float delta, TdRates rates);
    void unstage() { staged_ = false; }
    void keepAndDecay(float decay, std::uint32_t parts);
    void trainPart(WeightTable& w, std::uint32_t part) const;
    // chooseAction as it would be once the staged change is applied (before keepAndDecay): a single
    // update acts after its own learning step.
    std::uint32_t chooseActionStaged(const WeightTable& w, const std::vector<ActiveFeature>& phi, Rng& rng,
                                     std::vector<float>& activations, float& value, bool greedy,
                                     float uniformAtOrBelow) const;
    // A batch's prefetch of what trainPart reads: stage 0 the members that lead to it, stage 1 the
    // part boundaries, features, rows and step.
    void prefetchStaged(unsigned stage) const noexcept;
    // Blocks of 16 rows (threads seldom share a cache line), spread over the parts by a hash and a
    // multiply (no division: two per live trace were a tenth of a crowd's update).
    static std::uint32_t partOf(std::uint32_t feature, std::uint32_t parts) {
        return static_cast<std::uint32_t>((std::uint64_t((feature >> 4) * 0x9E3779B1u) * parts) >> 32);
    }

    // e = max(e, phi) for the critic; e_a = max(e_a, phi) for the chosen action's neuron (each
    // branch's, for a combined action). `continuous`: each continuous column's gradient g, whose
    // trace accumulates e_c += g * phi, kept within +-e (the value trace still decides liveness).
    void mark(const std::vector<ActiveFeature>& phi, std::uint32_t action, std::uint32_t featureCount,
              const float* continuous = nullptr);
    void clear();
    // Room for `features` features and a mark() of up to `active` features: mark() and
    // trainAndDecay() then allocate nothing. Scratch follows what is marked, not the feature count.
    void reserve(std::uint32_t features, std::size_t active);

    // A batch's prefetch (Agent::Impl::prefetch): the live list and the first lines of the traces
    // (all of a small agent's).
    void prefetch() const noexcept;
    // The same batch's PrefetchQueue: the live list and every trace.
    void addArraysTo(PrefetchQueue& q) const noexcept {
        q.add(live_.data(), std::size_t(liveCount_) * sizeof(std::uint32_t));
        q.add(traces_.data(), traces_.size() * sizeof(float));
    }

    std::uint32_t columns() const { return columns_; }  // actor neurons (one action set: one per action)
    std::uint32_t continuousColumns() const { return continuous_; }  // after them, in every row and trace
    std::uint32_t branchCount() const { return branchCount_; }  // 1: one action set
    const ActionBranches& branches() const { return branches_; }  // cold: read only with branches
    std::uint32_t liveCount() const { return liveCount_; }
    // Asks for the live features' trace rows (a batch, a few bodies ahead of their use).
    void prefetchLiveRows() const noexcept;
    // The live features (liveCount() of them) and every feature's traces (traceStride() each);
    // after keepAndDecay, what it kept: keptCount() features and their traces as they were.
    const std::uint32_t* live() const { return live_.data(); }
    const float* traces() const { return traces_.data(); }
    std::size_t keptCount() const { return staged_ ? stagedLive_.size() : 0; }
    const std::uint32_t* keptFeatures() const { return stagedLive_.data(); }
    const float* keptRows() const { return stagedRows_.data(); }
    std::uint32_t traceStride() const { return stride_; }
    std::vector<std::uint32_t> liveFeatures() const;
    std::vector<float> liveTraces() const;  // traceStride() values per live feature
    // Restores saved traces (validated by the caller).
    void restore(const std::vector<std::uint32_t>& features, const std::vector<float>& traces,
                 std::uint32_t featureCount);

private:
    // eta * delta per trace component, into `step` (stride_ values), delta clamped as trainAndDecay
    // explains; returns whether the actor's range can be crossed (then the trained rows are clamped).
    bool stepFor(float delta, TdRates rates, float* step) const;
    // A trained row's actor weights back in range: the discrete columns' within `range` when the
    // step was `bounded`, the continuous columns' always within +-ContinuousPolicy::kWeightBound
    // (their traces have either sign, so any step can cross it). trainAndDecay's kernel does the same.
    void clampRow(float* row, bool bounded, PolicyRange range) const;
    void grow(std::uint32_t featureCount);
    void reserveLive(std::size_t more);  // room for `more` live entries beyond liveCount_
    float* trace(std::uint32_t feature) { return traces_.data() + std::size_t(feature) * stride_; }

    std::uint32_t branchCount_;  // 1: one action set (branches_, cold, is then never read)
    std::uint32_t columns_;  // actor columns: numActions, or the branches' sizes summed
    std::uint32_t continuous_;  // continuous actions' columns, after them (0 without)
    std::uint32_t stride_;   // 1 + columns_ + continuous_: value trace, then one per actor column
    float threshold_;
    std::vector<float> traces_;         // per feature, stride_ values; zero unless live
    std::vector<std::uint32_t> live_;   // live features in its first liveCount_ entries (sized by need)
    std::uint32_t liveCount_ = 0;
    const Kernels* kernels_;            // chosen for this CPU (kernels.hpp)
    // Rarely used, so last (Agent::Impl puts them next to its cold members): eta * delta per
    // trace component is on the stack up to kStackStride components (a crowd's update then writes
    // no block of its own for it), else in step_.
    static constexpr std::uint32_t kStackStride = 16;
    std::vector<float> step_;
    // Staged training: the live features by part (partStart_[p] .. partStart_[p + 1]), their
    // traces as they were (stride_ values each, in the same order), the step.
    std::vector<std::uint32_t> partStart_;
    std::vector<std::uint32_t> stagedLive_;
    std::vector<float> stagedRows_;
    std::vector<float> stagedStep_;
    PolicyRange stagedRange_;
    bool stagedBounded_ = false;
    bool staged_ = false;
    ActionBranches branches_;
};

}  // namespace verve::core
