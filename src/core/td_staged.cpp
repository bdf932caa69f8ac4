// TdLearner's staged training: trainAndDecay split so that the bodies of one brain can train its
// weights on several threads at once, each thread owning a part of the features (shared_step.cpp).
#include <algorithm>

#include "core/continuous_actions.hpp"
#include "core/prefetch.hpp"
#include "core/td_learner.hpp"

namespace verve::core {

void TdLearner::reserveStaged(std::uint32_t parts) {
    // For the traces live now (stage() comes before the step marks new ones): a crowd's bodies keep
    // a copy of what their traces are, not of what they could be.
    reserveRoom(partStart_, std::size_t(parts) + 1);
    reserveRoom(stagedLive_, liveCount_);
    reserveRoom(stagedRows_, std::size_t(liveCount_) * stride_);
    reserveRoom(stagedStep_, stride_);
}

void TdLearner::stage(float delta, TdRates rates, std::uint32_t parts) {
    // Room was reserved (reserveStaged, reserve): nothing here allocates.
    stagedStep_.resize(stride_);
    stagedBounded_ = stepFor(delta, rates, stagedStep_.data());
    stagedRange_ = rates.policyRange;
    // A counting sort of the live features and their traces by part, each part in live-list order.
    partStart_.assign(std::size_t(parts) + 1, 0);
    for (std::uint32_t i = 0; i < liveCount_; ++i) ++partStart_[partOf(live_[i], parts) + 1];
    for (std::uint32_t p = 0; p < parts; ++p) partStart_[p + 1] += partStart_[p];
    stagedLive_.resize(liveCount_);
    stagedRows_.resize(std::size_t(liveCount_) * stride_);
    const std::size_t stride = stride_;
    // The live rows lie scattered over the traces and a crowd's are not in cache: each is asked for
    // 16 features ahead, as trainDecay's kernel does.
    constexpr std::uint32_t kAhead = 16;
    for (std::uint32_t i = 0; i < liveCount_; ++i) {
        if (i + kAhead < liveCount_) {
            prefetchLine(traces_.data() + std::size_t(live_[i + kAhead]) * stride);
            prefetchLineForWrite(stagedRows_.data() + std::size_t(i + kAhead) * stride);
        }
        const std::uint32_t at = partStart_[partOf(live_[i], parts)]++;
        stagedLive_[at] = live_[i];
        const float* e = traces_.data() + std::size_t(live_[i]) * stride;
        float* copy = stagedRows_.data() + std::size_t(at) * stride;
        for (std::size_t c = 0; c < stride; ++c) copy[c] = e[c];  // a few floats: no call to memmove
    }
    for (std::uint32_t p = parts; p > 0; --p) partStart_[p] = partStart_[p - 1];
    partStart_[0] = 0;
    staged_ = true;
}

void TdLearner::decayStaged(float decay) {
    // As trainDecay's kernel: a trace whose value component falls below the threshold is dropped
    // (zeroed), the live list compacted in order.
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < liveCount_; ++i) {
        const std::uint32_t feature = live_[i];
        float* e = traces_.data() + std::size_t(feature) * stride_;
        const bool keep = e[0] * decay >= threshold_;
        const float scale = keep ? decay : 0.0f;
        for (std::uint32_t c = 0; c < stride_; ++c) e[c] *= scale;
        live_[kept] = feature;
        kept += keep;
    }
    liveCount_ = kept;
}

void TdLearner::trainPart(WeightTable& w, std::uint32_t part) const {
    if (!staged_ || part + 1 >= partStart_.size()) return;
    const float* step = stagedStep_.data();
    const std::uint32_t begin = partStart_[part], end = partStart_[part + 1];
    // Each row clamped as soon as it is trained (no second pass over the scattered rows).
    const bool clamps = stagedBounded_ || continuous_ != 0;
    for (std::uint32_t i = begin; i < end; ++i) {
        float* row = w.row(stagedLive_[i]);
        const float* e = stagedRows_.data() + std::size_t(i) * stride_;
        for (std::uint32_t c = 0; c < stride_; ++c) row[c] += step[c] * e[c];
        if (clamps) clampRow(row, stagedBounded_, stagedRange_);
    }
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
        // Only features active at the trace threshold or more count: the rows mark() is about to
        // touch. The others (most of a 4-sigma neighbourhood) add less than the threshold times
        // their step each, and reading their rows was most of a crowd's update. As in mark(): a
        // branch-free filter first, then no branch on what the (uncached) rows hold, so that
        // their misses overlap.
        constexpr std::size_t kChunk = 64;
        ActiveFeature strong[kChunk];
        const std::size_t rows = traces_.size() / stride_;  // features made since the last mark have none
        for (std::size_t from = 0; from < phi.size(); from += kChunk) {
            const std::size_t end = std::min(phi.size(), from + kChunk);
            std::size_t n = 0;
            for (std::size_t i = from; i < end; ++i) {
                strong[n] = phi[i];
                n += phi[i].activation >= threshold_ && phi[i].index < rows;
            }
            for (std::size_t i = 0; i < n; ++i) {
                const float* e = traces_.data() + std::size_t(strong[i].index) * stride_;
                const float* row = w.row(strong[i].index);
                const float live = e[0] != 0.0f ? strong[i].activation : 0.0f;
                for (std::uint32_t c = 0; c < stride_; ++c) {
                    float moved = row[c] + stagedStep_[c] * e[c];
                    if (c >= WeightLayout::kPolicy + columns_) {
                        moved = std::clamp(moved, -ContinuousPolicy::kWeightBound, ContinuousPolicy::kWeightBound);
                    } else if (c >= WeightLayout::kPolicy && stagedBounded_) {
                        moved = stagedRange_.clamp(moved);
                    }
                    activations[c] += live * (moved - row[c]);
                }
            }
        }
    }
    return chooseFromSums(rng, activations, value, nullptr, greedy, uniformAtOrBelow);
}

void TdLearner::prefetchStaged(unsigned stage) const noexcept {
    if (stage == 0) {
        prefetchBytes(&partStart_, reinterpret_cast<const char*>(&stagedBounded_ + 1) - reinterpret_cast<const char*>(&partStart_));
        return;
    }
    prefetchData(partStart_);
    prefetchData(stagedLive_);
    prefetchData(stagedRows_);
    prefetchData(stagedStep_);
}

}  // namespace verve::core
