// TdLearner's staged training: trainAndDecay split so that the bodies of one brain can train its
// weights on several threads at once, each thread owning a part of the features (shared_step.cpp).
#include <Eigen/Core>

#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#endif

#include <algorithm>
#include <limits>
#include <type_traits>

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

void TdLearner::stage(float delta, TdRates rates) {
    // Room was reserved (reserveStaged, reserve): nothing here allocates.
    stagedStep_.resize(stride_);
    stagedBounded_ = stepFor(delta, rates, stagedStep_.data());
    stagedRange_ = rates.policyRange;
    staged_ = true;
}

namespace {

// keepAndDecay's pass over the live rows, as trainDecay's kernel decays them: a trace whose value
// component falls below the threshold is dropped (zeroed), the live list compacted in order. Each
// row is copied as it was first, to its place in its part (`next`: each part's next place).
// Locals only: a store through a member's pointer could change any member as far as the
// compiler knows. Returns how many stay live.
template <std::uint32_t S>
std::uint32_t keepRows(std::uint32_t* __restrict live, std::uint32_t count, float* __restrict traces, std::uint32_t stride,
                       std::uint32_t parts, std::uint32_t* __restrict next, std::uint32_t* __restrict keptFeatures,
                       float* __restrict keptRows, float decay, float threshold) {
    if (S != 0) stride = S;
    // The live rows lie scattered over the traces and a crowd's are not in cache: each is asked for
    // 16 features ahead, as trainDecay's kernel does.
    constexpr std::uint32_t kAhead = 16;
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t feature = live[i];
        if (i + kAhead < count) {
            prefetchLineForWrite(traces + std::size_t(live[i + kAhead]) * stride);
            prefetchLineForWrite(keptRows + std::size_t(i + kAhead) * stride);
        }
        const std::uint32_t at = next[TdLearner::partOf(feature, parts)]++;
        keptFeatures[at] = feature;
        float* e = traces + std::size_t(feature) * stride;
        float* copy = keptRows + std::size_t(at) * stride;
        const bool keep = e[0] * decay >= threshold;
        const float scale = keep ? decay : 0.0f;
        std::uint32_t c = 0;
        if constexpr (S != 0) {
            for (; c + 4 <= S; c += 4) {
                Eigen::Map<Eigen::Array4f> x(e + c);
                Eigen::Map<Eigen::Array4f>(copy + c) = x;
                x *= scale;
            }
        }
        for (; c < stride; ++c) {
            copy[c] = e[c];
            e[c] *= scale;
        }
        live[kept] = feature;
        kept += keep;
    }
    return kept;
}

// The hot loops of the staged step, for S trace components known at compile time (0: any) and
// one clamp or none, so that a row's few columns take no loop or branch of their own. The same
// operations in the same order as the general form: the results are those of any S.
struct StagedRows {
    const float* step;
    std::uint32_t stride;       // trace components (S, when S != 0)
    std::uint32_t discrete;     // discrete actor columns, from 1 on
    PolicyRange range;          // theirs, when bounded
    std::uint32_t continuous;   // continuous actor columns after them, within +-kWeightBound
};

// A column's weight after its step: the discrete actor columns within the range when the step is
// bounded, the continuous ones within +-kWeightBound.
template <bool Bounded>
VERVE_ALWAYS_INLINE float clampedColumn(const StagedRows& r, std::uint32_t c, float moved) {
    if (c >= WeightLayout::kPolicy + r.discrete) {
        return std::clamp(moved, -ContinuousPolicy::kWeightBound, ContinuousPolicy::kWeightBound);
    }
    if (Bounded && c >= WeightLayout::kPolicy) return r.range.clamp(moved);
    return moved;
}

// A column's bounds as clampedColumn applies them, for S columns known at compile time: the
// value's and an unbounded step's actor columns [-inf, inf], which leaves any weight as it is.
template <std::uint32_t S, bool Bounded>
struct ColumnBounds {
    float lo[S], hi[S];
    explicit ColumnBounds(const StagedRows& r) {
        constexpr float inf = std::numeric_limits<float>::infinity();
        for (std::uint32_t c = 0; c < S; ++c) {
            const bool continuous = c >= WeightLayout::kPolicy + r.discrete;
            const bool bounded = Bounded && c >= WeightLayout::kPolicy;
            lo[c] = continuous ? -ContinuousPolicy::kWeightBound : bounded ? r.range.low : -inf;
            hi[c] = continuous ? ContinuousPolicy::kWeightBound : bounded ? r.range.high : inf;
        }
    }
};

// std::clamp's min(max(x, lo), hi), per lane: as clampedColumn, bit for bit.
using Quad = Eigen::Array4f;
// (Eigen's select became a max and a min per lane, stored to the stack and read back as one
// vector: a stalled store forwarding on every row, most of a crowd's choice. SSE's maxps(lo, x) is
// lo > x ? lo : x and minps(hi, r) is hi < r ? hi : r, the same operations.)
VERVE_ALWAYS_INLINE Quad clampQuad(const Quad& x, const Quad& lo, const Quad& hi) {
#if defined(__SSE__) || defined(_M_X64)
    Quad out;
    _mm_storeu_ps(out.data(), _mm_min_ps(_mm_loadu_ps(hi.data()), _mm_max_ps(_mm_loadu_ps(lo.data()), _mm_loadu_ps(x.data()))));
    return out;
#else
    const Quad raised = (x < lo).select(lo, x);
    return (hi < raised).select(hi, raised);
#endif
}
VERVE_ALWAYS_INLINE float clampOne(float x, float lo, float hi) {
    const float raised = x < lo ? lo : x;
    return hi < raised ? hi : raised;
}

// trainPart's rows: each takes step * e, then its clamps. With S known, the columns unrolled
// (the same multiply, add and clamp per column) and the table's base and stride in registers.
template <std::uint32_t S, bool Bounded>
void trainRows(const StagedRows& r, WeightTable& w, const std::uint32_t* features, const float* rows, std::uint32_t count) {
    if constexpr (S == 0) {
        for (std::uint32_t i = 0; i < count; ++i) {
            float* row = w.row(features[i]);
            const float* e = rows + std::size_t(i) * r.stride;
            for (std::uint32_t c = 0; c < r.stride; ++c) row[c] = clampedColumn<Bounded>(r, c, row[c] + r.step[c] * e[c]);
        }
    } else {
        const ColumnBounds<S, Bounded> b(r);
        float step[S];
        for (std::uint32_t c = 0; c < S; ++c) step[c] = r.step[c];
        float* const weights = w.data().data();
        const std::size_t stride = w.stride();
        for (std::uint32_t i = 0; i < count; ++i) {
            float* row = weights + features[i] * stride;
            const float* e = rows + std::size_t(i) * S;
            for (std::uint32_t c = 0; c < S; ++c) row[c] = clampOne(row[c] + step[c] * e[c], b.lo[c], b.hi[c]);
        }
    }
}

// chooseActionStaged's correction: for each of the n features (strong: active at the trace
// threshold), what its row's own step adds to the sums, when its trace is live. With S known, 4
// columns at a time, summed in registers (each column's sum in feature order, as the general form).
template <std::uint32_t S, bool Bounded>
void addOwnStep(const StagedRows& r, const WeightTable& w, const float* traces, const ActiveFeature* strong, std::size_t n,
                float* sums) {
    if constexpr (S == 0) {
        for (std::size_t i = 0; i < n; ++i) {
            const float* e = traces + std::size_t(strong[i].index) * r.stride;
            const float* row = w.row(strong[i].index);
            const float live = e[0] != 0.0f ? strong[i].activation : 0.0f;
            for (std::uint32_t c = 0; c < r.stride; ++c) {
                const float moved = clampedColumn<Bounded>(r, c, row[c] + r.step[c] * e[c]);
                sums[c] += live * (moved - row[c]);
            }
        }
    } else {
        const ColumnBounds<S, Bounded> b(r);
        constexpr std::uint32_t kQuads = S / 4;
        Quad quads[kQuads > 0 ? kQuads : 1];
        float rest[S % 4 > 0 ? S % 4 : 1];
        for (std::uint32_t q = 0; q < kQuads; ++q) quads[q] = Eigen::Map<const Quad>(sums + 4 * q);
        for (std::uint32_t c = 4 * kQuads; c < S; ++c) rest[c - 4 * kQuads] = sums[c];
        for (std::size_t i = 0; i < n; ++i) {
            const float* e = traces + std::size_t(strong[i].index) * S;
            const float* row = w.row(strong[i].index);
            const float live = e[0] != 0.0f ? strong[i].activation : 0.0f;
            for (std::uint32_t q = 0; q < kQuads; ++q) {
                const Eigen::Map<const Quad> x(row + 4 * q);
                const Quad moved = clampQuad(x + Eigen::Map<const Quad>(r.step + 4 * q) * Eigen::Map<const Quad>(e + 4 * q),
                                             Eigen::Map<const Quad>(b.lo + 4 * q), Eigen::Map<const Quad>(b.hi + 4 * q));
                quads[q] += live * (moved - x);
            }
            for (std::uint32_t c = 4 * kQuads; c < S; ++c) {
                rest[c - 4 * kQuads] += live * (clampOne(row[c] + r.step[c] * e[c], b.lo[c], b.hi[c]) - row[c]);
            }
        }
        for (std::uint32_t q = 0; q < kQuads; ++q) Eigen::Map<Quad>(sums + 4 * q) = quads[q];
        for (std::uint32_t c = 4 * kQuads; c < S; ++c) sums[c] = rest[c - 4 * kQuads];
    }
}

// Calls f.template operator()<S, Bounded>() with S the stride when it is a common one (else 0).
template <typename F>
void withStride(std::uint32_t stride, bool bounded, F&& f) {
    const auto go = [&](auto s) {
        if (bounded) f(std::integral_constant<std::uint32_t, decltype(s)::value>{}, std::true_type{});
        else f(std::integral_constant<std::uint32_t, decltype(s)::value>{}, std::false_type{});
    };
    switch (stride) {
        case 3: return go(std::integral_constant<std::uint32_t, 3>{});
        case 4: return go(std::integral_constant<std::uint32_t, 4>{});
        case 5: return go(std::integral_constant<std::uint32_t, 5>{});
        case 6: return go(std::integral_constant<std::uint32_t, 6>{});
        default: return go(std::integral_constant<std::uint32_t, 0>{});
    }
}

}  // namespace

void TdLearner::keepAndDecay(float decay, std::uint32_t parts) {
    // A counting sort of the live features and their traces by part, each part in live-list order.
    // (Locals: a store to the counts could change liveCount_ as far as the compiler knows.)
    partStart_.assign(std::size_t(parts) + 1, 0);
    std::uint32_t* const counts = partStart_.data() + 1;
    const std::uint32_t* const live = live_.data();
    const std::uint32_t count = liveCount_;
    if (parts == 1) counts[0] = count;
    else for (std::uint32_t i = 0; i < count; ++i) ++counts[partOf(live[i], parts)];
    for (std::uint32_t p = 0; p < parts; ++p) partStart_[p + 1] += partStart_[p];
    stagedLive_.resize(liveCount_);
    stagedRows_.resize(std::size_t(liveCount_) * stride_);
    const auto keep = [&](auto s) {
        return keepRows<decltype(s)::value>(live_.data(), liveCount_, traces_.data(), stride_, parts, partStart_.data(),
                                            stagedLive_.data(), stagedRows_.data(), decay, threshold_);
    };
    switch (stride_) {
        case 3: liveCount_ = keep(std::integral_constant<std::uint32_t, 3>{}); break;
        case 4: liveCount_ = keep(std::integral_constant<std::uint32_t, 4>{}); break;
        case 5: liveCount_ = keep(std::integral_constant<std::uint32_t, 5>{}); break;
        case 6: liveCount_ = keep(std::integral_constant<std::uint32_t, 6>{}); break;
        default: liveCount_ = keep(std::integral_constant<std::uint32_t, 0>{}); break;
    }
    for (std::uint32_t p = parts; p > 0; --p) partStart_[p] = partStart_[p - 1];
    partStart_[0] = 0;
}

void TdLearner::trainPart(WeightTable& w, std::uint32_t part) const {
    if (!staged_ || part + 1 >= partStart_.size()) return;
    const std::uint32_t begin = partStart_[part], end = partStart_[part + 1];
    // Each row clamped as soon as it is trained (no second pass over the scattered rows).
    const StagedRows r{stagedStep_.data(), stride_, columns_, stagedRange_, continuous_};
    withStride(stride_, stagedBounded_, [&](auto s, auto bounded) {
        trainRows<decltype(s)::value, decltype(bounded)::value>(r, w, stagedLive_.data() + begin,
                                                                 stagedRows_.data() + std::size_t(begin) * stride_, end - begin);
    });
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
        // Features made since the last mark have no trace row (a feature index fits in 32 bits).
        const auto rows = static_cast<std::uint32_t>(traces_.size() / stride_);
        const StagedRows r{stagedStep_.data(), stride_, columns_, stagedRange_, continuous_};
        for (std::size_t from = 0; from < phi.size(); from += kChunk) {
            const std::size_t n = kernels_->strongFeatures(phi.data() + from, std::min(kChunk, phi.size() - from), threshold_,
                                                           rows, strong);
            withStride(stride_, stagedBounded_, [&](auto s, auto bounded) {
                addOwnStep<decltype(s)::value, decltype(bounded)::value>(r, w, traces_.data(), strong, n, activations.data());
            });
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
