#include "core/td_learner.hpp"

#include <algorithm>
#include <cmath>

#include "core/continuous_actions.hpp"
#include "core/prefetch.hpp"

namespace verve::core {

namespace {

// A hopeless state, or activations that are not finite: a uniform choice among the allowed.
std::uint32_t uniformAllowed(Rng& rng, std::uint32_t n, const std::uint8_t* allowed) {
    if (allowed == nullptr) return rng.below(n);
    std::uint32_t count = 0;
    for (std::uint32_t a = 0; a < n; ++a) count += actionAllowed(allowed, a);
    std::uint32_t pick = rng.below(count);
    for (std::uint32_t a = 0; a < n; ++a) {
        if (actionAllowed(allowed, a) && pick-- == 0) return a;
    }
    return 0;  // unreachable: callers allow at least one action of each branch
}

// One branch's choice among its n activations y (allowed: its n flags or nullptr), as
// chooseFromSums describes. Inlined: one action set calls it once per update.
VERVE_ALWAYS_INLINE std::uint32_t chooseIn(Rng& rng, float* y, std::uint32_t n, const std::uint8_t* allowed, bool greedy,
                                           bool uniform) {
    // The largest preference, not the largest activation: sigmoids that saturate at 1 or
    // underflow to 0 tie in float where their preferences still differ.
    std::uint32_t best = n;
    for (std::uint32_t a = 0; a < n; ++a) {
        if (actionAllowed(allowed, a) && (best == n || y[a] > y[best])) best = a;
    }
    const float top = y[best];
    // Preferences below about -88 underflow every sigmoid to 0. There y_a = e^(x_a) to float
    // precision, so the roulette's proportions are e^(x_a - x_max): taken relative to the largest,
    // the choice still follows the preferences instead of turning uniform where float runs out.
    const bool underflowed = sigmoid(top) == 0.0f && std::isfinite(top);
    float total = 0.0f;
    for (std::uint32_t a = 0; a < n; ++a) {
        if (!actionAllowed(allowed, a)) y[a] = 0.0f;
        else y[a] = underflowed ? std::exp(y[a] - top) : sigmoid(y[a]);
        total += y[a];
    }
    if (greedy) return best;
    if (!(total > 0.0f) || !std::isfinite(total) || uniform) return uniformAllowed(rng, n, allowed);
    // Roulette (winner-take-all): each action in proportion to its neuron's activation.
    float pick = rng.uniform() * total;
    for (std::uint32_t a = 0; a < n; ++a) {
        pick -= y[a];
        if (pick < 0.0f) return a;
    }
    // Rounding left a sliver: the last action with any activation takes it.
    for (std::uint32_t a = n; a-- > 0;) {
        if (y[a] > 0.0f) return a;
    }
    return best;
}

}  // namespace

TdLearner::TdLearner(const ActionBranches& branches, std::uint32_t continuousColumns, float traceThreshold)
    : branchCount_(branches.count), columns_(branches.columns), continuous_(continuousColumns),
      stride_(1 + branches.columns + continuousColumns), threshold_(traceThreshold),
      kernels_(&kernels()), branches_(branches) {
    if (stride_ > kStackStride) step_.resize(stride_);
}

void TdLearner::reserve(std::uint32_t features, std::size_t active) {
    reserveRoom(traces_, std::size_t(features) * stride_);
    // At most `active` more traces become live (and one spare slot, reserveLive()).
    reserveRoom(live_, std::min<std::size_t>(liveCount_ + active, features) + 1);
}

float TdLearner::value(const WeightTable& w, const std::vector<ActiveFeature>& phi, PrefetchQueue* ahead) const {
    float v = 0.0f;
    kernels_->rowSums(w.data().data(), w.stride(), phi.data(), phi.size(), 1, &v, ahead);
    return v;
}

std::uint32_t TdLearner::chooseAction(const WeightTable& w, const std::vector<ActiveFeature>& phi, Rng& rng,
                                      std::vector<float>& activations, float& value, const std::uint8_t* allowed,
                                      bool greedy, float uniformAtOrBelow, PrefetchQueue* ahead) const {
    // One pass over a row's first columns, [value, policy[A]].
    activations.resize(stride_);
    kernels_->rowSums(w.data().data(), w.stride(), phi.data(), phi.size(), stride_, activations.data(), ahead);
    return chooseFromSums(rng, activations, value, allowed, greedy, uniformAtOrBelow);
}

std::uint32_t TdLearner::chooseFromSums(Rng& rng, std::vector<float>& activations, float& value,
                                        const std::uint8_t* allowed, bool greedy, float uniformAtOrBelow) const {
    // The value leaves the front.
    value = activations[WeightLayout::kValue];
    activations.erase(activations.begin());
    const bool uniform = value <= uniformAtOrBelow;
    if (branchCount_ == 1) return chooseIn(rng, activations.data(), columns_, allowed, greedy, uniform);
    std::uint32_t action = 0, scale = 1;
    for (std::uint32_t b = 0; b < branches_.count; ++b) {
        const std::uint32_t at = branches_.offset[b], n = branches_.size[b];
        action += scale * chooseIn(rng, activations.data() + at, n, allowed == nullptr ? nullptr : allowed + at, greedy, uniform);
        scale *= n;
    }
    return action;
}

bool TdLearner::stepFor(float delta, TdRates rates, float* step) const {
    // Learning never takes a weight step near kStepLimit (it bootstraps from bounded values), but
    // weights a hostile save brings up to AgentSnapshot::kWeightLimit could make one: clamped, every
    // step stays below half the float spacing at that limit, so no weight can be pushed past it.
    const float fastest = std::max(std::fabs(rates.value), std::fabs(rates.policy));
    if (fastest > 0.0f) delta = std::clamp(delta, -kStepLimit / fastest, kStepLimit / fastest);
    // A trace row [value, policy[A]] lines up with the first 1 + A weights of its feature's row.
    std::fill_n(step, stride_, rates.policy * delta);
    step[0] = rates.value * delta;
    // Bounded actor weights: every row trained now is clamped after the kernel has moved it. The
    // discrete neurons' traces are never negative (mark() keeps the larger of activation and trace;
    // the continuous columns', of either sign, are clamped apart), so every such actor weight
    // moves the way rates.policy * delta points: only when that side is bounded is there anything
    // to clamp (with the habit ceiling alone, only after a positive TD error).
    return rates.policyRange.crossable(rates.policy * delta);
}

void TdLearner::trainAndDecay(WeightTable& w, float delta, TdRates rates, float decay, PrefetchQueue* ahead) {
    float onStack[kStackStride];
    float* step = stride_ <= kStackStride ? onStack : step_.data();
    const bool bounded = stepFor(delta, rates, step);
    TraceStep s;
    s.step = step;
    s.traceStride = stride_;
    s.weightStride = w.stride();
    s.decay = decay;
    s.threshold = threshold_;
    s.ahead = ahead;
    // The kernel clamps each row as it trains it (clampPolicy and clampContinuous, row by row).
    s.clampsDiscrete = bounded;
    s.discreteColumns = columns_;
    s.low = rates.policyRange.low;
    s.high = rates.policyRange.high;
    s.boundedColumns = continuous_;
    s.bound = ContinuousPolicy::kWeightBound;
    liveCount_ = kernels_->trainDecay(s, w.data().data(), traces_.data(), live_.data(), liveCount_);
}

void TdLearner::clampRow(float* row, bool bounded, PolicyRange range) const {
    float* policy = row + WeightLayout::kPolicy;
    if (bounded) {
        for (std::uint32_t a = 0; a < columns_; ++a) policy[a] = range.clamp(policy[a]);
    }
    constexpr float bound = ContinuousPolicy::kWeightBound;
    for (std::uint32_t j = 0; j < continuous_; ++j) policy[columns_ + j] = std::clamp(policy[columns_ + j], -bound, bound);
}

void TdLearner::grow(std::uint32_t featureCount) {
    if (traces_.size() < std::size_t(featureCount) * stride_) traces_.resize(std::size_t(featureCount) * stride_, 0.0f);
}

void TdLearner::reserveLive(std::size_t more) {
    // One spare slot: mark() writes a candidate entry before it knows whether it is new.
    if (live_.size() < liveCount_ + more + 1) live_.resize(liveCount_ + more + 1);
}

void TdLearner::mark(const std::vector<ActiveFeature>& phi, std::uint32_t action, std::uint32_t featureCount,
                     const float* continuous) {
    grow(featureCount);
    // The actor column of each branch's choice (one action set: the action).
    std::uint32_t column[ActionBranches::kMax];
    column[0] = action;
    const std::uint32_t columns = branchCount_ == 1 ? 1 : branches_.columnsOf(action, column);
    // Below the threshold a trace would be dropped at the next decay anyway, and in a 4-sigma
    // neighbourhood most features are below it: a sequential, branch-free filter first (4 features
    // per instruction with AVX2, Kernels::strongFeatures), so that only the features that mark
    // anything touch the (randomly placed) trace rows.
    // The filter writes to the stack, a chunk at a time: a buffer of the agent's own would be one
    // more cold block for every update of a crowd.
    constexpr std::size_t kChunk = 64;
    ActiveFeature strong[kChunk];
    for (std::size_t from = 0; from < phi.size(); from += kChunk) {
        const std::size_t n = kernels_->strongFeatures(phi.data() + from, std::min(kChunk, phi.size() - from), threshold_,
                                                       UINT32_MAX, strong);
        reserveLive(std::min<std::size_t>(n, featureCount - liveCount_));  // at most that many become live
        // Locals, not members: a store to live_ may alias the member count as far as the compiler
        // knows, which then went through memory on every feature, one serial chain.
        float* const traces = traces_.data();
        std::uint32_t* const live = live_.data();
        const std::size_t stride = stride_;
        const std::size_t first = 1 + column[0];  // the first branch's trace (one action set: the action's)
        std::uint32_t count = liveCount_;
        for (std::size_t i = 0; i < n; ++i) {
            const ActiveFeature& f = strong[i];
            float* e = traces + f.index * stride;
            live[count] = f.index;
            count += e[0] == 0.0f;  // newly live (a live value trace is > 0)
            // Each max written as the instruction computes it (the larger, else the trace), and both
            // read before either is written: no branch on the data.
            const float a = f.activation, v = e[0], p = e[first];
            e[0] = a > v ? a : v;
            e[first] = a > p ? a : p;
        }
        liveCount_ = count;
        // The other branches' chosen neurons, apart: one action set's loop above stays as it was.
        for (std::size_t i = 0; i < n && columns > 1; ++i) {
            float* e = traces + strong[i].index * stride;
            for (std::uint32_t b = 1; b < columns; ++b) e[1 + column[b]] = std::max(strong[i].activation, e[1 + column[b]]);
        }
        // The continuous actions' accumulating traces, after the value trace took its max.
        for (std::size_t i = 0; i < n && continuous != nullptr; ++i) {
            float* e = traces + strong[i].index * stride + 1 + columns_;
            const float limit = e[-1 - std::ptrdiff_t(columns_)];
            for (std::uint32_t c = 0; c < continuous_; ++c) {
                e[c] = std::clamp(e[c] + continuous[c] * strong[i].activation, -limit, limit);
            }
        }
    }
}

void TdLearner::clear() {
    for (std::uint32_t i = 0; i < liveCount_; ++i) std::fill_n(trace(live_[i]), stride_, 0.0f);
    liveCount_ = 0;
}

std::vector<std::uint32_t> TdLearner::liveFeatures() const {
    return std::vector<std::uint32_t>(live_.begin(), live_.begin() + liveCount_);
}

std::vector<float> TdLearner::liveTraces() const {
    std::vector<float> out;
    out.reserve(std::size_t(liveCount_) * stride_);
    for (std::uint32_t i = 0; i < liveCount_; ++i) {
        const float* e = traces_.data() + std::size_t(live_[i]) * stride_;
        out.insert(out.end(), e, e + stride_);
    }
    return out;
}

void TdLearner::restore(const std::vector<std::uint32_t>& features, const std::vector<float>& traces,
                        std::uint32_t featureCount) {
    clear();
    grow(featureCount);
    reserveLive(features.size());
    for (std::size_t i = 0; i < features.size(); ++i) {
        std::copy_n(traces.data() + i * stride_, stride_, trace(features[i]));
        live_[liveCount_++] = features[i];
    }
}

void TdLearner::prefetchLiveRows() const noexcept {
    // At most 64 lines: a crowd's agents have a few dozen live traces; more would crowd out the rest.
    const std::uint32_t n = std::min<std::uint32_t>(liveCount_, 64);
    for (std::uint32_t i = 0; i < n; ++i) prefetchLineForWrite(traces_.data() + std::size_t(live_[i]) * stride_);
}

void TdLearner::prefetch() const noexcept {
    prefetchBytes(live_.data(), std::size_t(liveCount_) * sizeof(std::uint32_t));
    prefetchData(traces_);
}

}  // namespace verve::core
