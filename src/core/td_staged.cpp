// TdLearner's staged training: trainAndDecay split so that the bodies of one brain can train its
// weights on several threads at once, each thread owning a part of the features (shared_step.hpp).
#include <algorithm>

#include "core/td_learner.hpp"

namespace verve::core {

void TdLearner::reserveStaged(std::uint32_t parts) {
    reserveRoom(stagedLive_, live_.capacity());
    reserveRoom(trained_, live_.capacity());
    reserveRoom(partStart_, std::size_t(parts) + 1);
    reserveRoom(stagedStep_, stride_);
}

void TdLearner::stage(float delta, TdRates rates, float decay, std::uint32_t parts) {
    // Room was reserved (reserveStaged, reserve): nothing here allocates.
    stagedStep_.resize(stride_);
    stagedBounded_ = stepFor(delta, rates, stagedStep_.data());
    stagedRange_ = rates.policyRange;
    stagedDecay_ = decay;
    // A counting sort of the live features by part, each part in live-list order.
    partStart_.assign(std::size_t(parts) + 1, 0);
    for (std::uint32_t i = 0; i < liveCount_; ++i) ++partStart_[partOf(live_[i], parts) + 1];
    for (std::uint32_t p = 0; p < parts; ++p) partStart_[p + 1] += partStart_[p];
    stagedLive_.resize(liveCount_);
    for (std::uint32_t i = 0; i < liveCount_; ++i) stagedLive_[partStart_[partOf(live_[i], parts)]++] = live_[i];
    for (std::uint32_t p = parts; p > 0; --p) partStart_[p] = partStart_[p - 1];
    partStart_[0] = 0;
    // The kernel compacts each part's entries as it drops traces; a bounded step clamps them all.
    if (stagedBounded_) trained_.assign(stagedLive_.begin(), stagedLive_.end());
    staged_ = true;
}

void TdLearner::trainPart(WeightTable& w, std::uint32_t part) {
    if (!staged_ || part + 1 >= partStart_.size()) return;
    const std::uint32_t begin = partStart_[part], count = partStart_[part + 1] - begin;
    if (count == 0) return;
    TraceStep s;
    s.step = stagedStep_.data();
    s.traceStride = stride_;
    s.weightStride = w.stride();
    s.decay = stagedDecay_;
    s.threshold = threshold_;
    kernels_->trainDecay(s, w.data().data(), traces_.data(), stagedLive_.data() + begin, count);
    if (stagedBounded_) clampPolicy(w, trained_.data() + begin, count, stagedRange_);
}

std::uint32_t TdLearner::chooseActionStaged(const WeightTable& w, const std::vector<ActiveFeature>& phi, Rng& rng,
                                            std::vector<float>& activations, float& value, bool greedy,
                                            float uniformAtOrBelow) const {
    activations.resize(stride_);
    kernels_->rowSums(w.data().data(), w.stride(), phi.data(), phi.size(), stride_, activations.data(), nullptr);
    if (staged_) {
        // The body's own step on the rows it reads: a feature's trace is zero unless it is live,
        // and a live one's row takes w + step * e (an actor weight clamped to its range, as
        // trainPart; the sums' rounding may differ from a single update's, never between threads).
        for (const ActiveFeature& f : phi) {
            // A feature made since this body last marked lies beyond its traces: not live.
            if (std::size_t(f.index) * stride_ >= traces_.size()) continue;
            const float* e = traces_.data() + std::size_t(f.index) * stride_;
            if (e[0] == 0.0f) continue;
            const float* row = w.row(f.index);
            for (std::uint32_t c = 0; c < stride_; ++c) {
                float moved = row[c] + stagedStep_[c] * e[c];
                if (c >= WeightLayout::kPolicy && stagedBounded_) moved = stagedRange_.clamp(moved);
                activations[c] += f.activation * (moved - row[c]);
            }
        }
    }
    return chooseFromSums(rng, activations, value, nullptr, greedy, uniformAtOrBelow);
}

void TdLearner::finishStaged() {
    if (!staged_) return;
    // A dropped trace is zero (the kernel zeroes it) and a kept one is at least the threshold:
    // the live list keeps its order, whatever the number of parts.
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < liveCount_; ++i) {
        const std::uint32_t feature = live_[i];
        live_[kept] = feature;
        kept += traces_[std::size_t(feature) * stride_] != 0.0f;
    }
    liveCount_ = kept;
    staged_ = false;
}

}  // namespace verve::core
