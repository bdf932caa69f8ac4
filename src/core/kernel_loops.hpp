// Loop shapes shared by the kernel sets (kernels_portable.cpp, kernels_avx2.cpp). Each set
// instantiates them with its own 4-wide step, a type from its anonymous namespace, so every
// instantiation stays private to its file: the AVX2 one can never be handed to other code.
#pragma once
#include <cstddef>
#include <cstdint>

#include "core/kernels.hpp"
#include "core/prefetch.hpp"

namespace verve::core {

// Kernels::strongFeatures one feature at a time, branch-free, from phi[from] on with `written`
// already out (the portable set; the AVX2 set's last few). A template of the set's own Quad4, as
// the loops below.
template <typename Quad4>
std::size_t strongFeaturesFrom(const ActiveFeature* phi, std::size_t from, std::size_t n, float threshold,
                               std::uint32_t below, ActiveFeature* out, std::size_t written) {
    for (std::size_t i = from; i < n; ++i) {
        out[written] = phi[i];
        written += phi[i].activation >= threshold && phi[i].index < below;
    }
    return written;
}

// Which clamps trainDecayRows applies to each trained row (TraceStep): none; the discrete actor
// columns, all of a trace's actor columns (the common bounded case: their count is known with S);
// or any, as the step says.
enum class RowClamp { None, Discrete, Any };

// S trace components, known at compile time for the common action counts (0: s.traceStride).
// Quad4::train(w, e, step, scale) does, for 4 components, w += step * e, then e *= scale.
// The clamps as std::clamp computes them, min(max(w, low), high), written out: std::clamp
// instantiated in the AVX2 file could be the copy the linker keeps for the whole library.
template <std::uint32_t S, RowClamp Clamp, typename Quad4>
std::uint32_t trainDecayRows(const TraceStep& s, float* __restrict weights, float* __restrict traces,
                             std::uint32_t* __restrict live, std::uint32_t count) {
    const std::uint32_t stride = S != 0 ? S : s.traceStride;
    const std::size_t weightStride = s.weightStride;
    const float* __restrict step = s.step;
    const float decay = s.decay, threshold = s.threshold;
    const float low = s.low, high = s.high, bound = s.bound;
    const std::uint32_t clamped = Clamp == RowClamp::Discrete ? stride - 1 : s.clampsDiscrete ? s.discreteColumns : 0;
    const std::uint32_t boundedFrom = 1 + (Clamp == RowClamp::Discrete ? stride - 1 : s.discreteColumns);
    const std::uint32_t boundedTo = boundedFrom + (Clamp == RowClamp::Discrete ? 0 : s.boundedColumns);
    // Discrete clamps with S known: per component bounds, the value's unbounded (a clamp to
    // [-inf, inf] leaves any value as it is), so that Quad4 clamps 4 components at once.
    constexpr bool quadClamps = Clamp == RowClamp::Discrete && S != 0;
    constexpr float kInfinity = __builtin_inff();  // not numeric_limits: no shared inline function here
    float lo[S != 0 ? S : 1], hi[S != 0 ? S : 1];
    if (quadClamps) {
        for (std::uint32_t k = 0; k < stride; ++k) {
            lo[k] = k == 0 ? -kInfinity : low;
            hi[k] = k == 0 ? kInfinity : high;
        }
    }
    std::uint32_t kept = 0;
    // The live rows lie scattered over the feature arrays, and in a crowd they are not in cache:
    // rows asked for kAhead features early arrive while this one trains (a 10,000-agent
    // cart-pole crowd: ~13% less time per update, docs/performance.md). live[i + kAhead] is
    // still unread: compaction only writes at or below i.
    constexpr std::uint32_t kAhead = 16;
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t feature = live[i];
        askAhead(s.ahead, 1);
        if (i + kAhead < count) {
            prefetchLineForWrite(traces + std::size_t(live[i + kAhead]) * stride);
            prefetchLineForWrite(weights + std::size_t(live[i + kAhead]) * weightStride);
        }
        float* __restrict w = weights + feature * weightStride;
        float* __restrict e = traces + std::size_t(feature) * stride;
        // The value component decides whether the trace stays live; a dropped one is zeroed,
        // branch-free, and the live list is compacted in order.
        const bool keep = e[0] * decay >= threshold;
        const float scale = keep ? decay : 0.0f;
        std::uint32_t k = 0;
        if (quadClamps) {
            for (; k + 4 <= stride; k += 4) Quad4::trainClamped(w + k, e + k, step + k, scale, lo + k, hi + k);
            for (; k < stride; ++k) {
                const float moved = w[k] + step[k] * e[k];
                const float raised = moved < lo[k] ? lo[k] : moved;
                w[k] = hi[k] < raised ? hi[k] : raised;
                e[k] *= scale;
            }
            live[kept] = feature;
            kept += keep;
            continue;
        }
        for (; k + 4 <= stride; k += 4) Quad4::train(w + k, e + k, step + k, scale);
        for (; k < stride; ++k) {
            w[k] += step[k] * e[k];
            e[k] *= scale;
        }
        if (Clamp != RowClamp::None) {
            for (std::uint32_t a = 1; a <= clamped; ++a) {
                const float raised = w[a] < low ? low : w[a];
                w[a] = high < raised ? high : raised;
            }
            for (std::uint32_t j = boundedFrom; j < boundedTo; ++j) {
                const float raised = w[j] < -bound ? -bound : w[j];
                w[j] = bound < raised ? bound : raised;
            }
        }
        live[kept] = feature;
        kept += keep;
    }
    return kept;
}

template <RowClamp Clamp, typename Quad4>
std::uint32_t trainDecayStride(const TraceStep& s, float* weights, float* traces, std::uint32_t* live,
                               std::uint32_t count) {
    switch (s.traceStride) {  // 1 + actions
        case 3: return trainDecayRows<3, Clamp, Quad4>(s, weights, traces, live, count);
        case 4: return trainDecayRows<4, Clamp, Quad4>(s, weights, traces, live, count);
        case 5: return trainDecayRows<5, Clamp, Quad4>(s, weights, traces, live, count);
        case 6: return trainDecayRows<6, Clamp, Quad4>(s, weights, traces, live, count);
        case 9: return trainDecayRows<9, Clamp, Quad4>(s, weights, traces, live, count);
        default: return trainDecayRows<0, Clamp, Quad4>(s, weights, traces, live, count);
    }
}

// Kernels::trainDecay for a kernel set.
template <typename Quad4>
std::uint32_t trainDecay(const TraceStep& s, float* weights, float* traces, std::uint32_t* live,
                             std::uint32_t count) {
    if (s.boundedColumns != 0) return trainDecayStride<RowClamp::Any, Quad4>(s, weights, traces, live, count);
    if (!s.clampsDiscrete) return trainDecayStride<RowClamp::None, Quad4>(s, weights, traces, live, count);
    if (s.discreteColumns + 1 == s.traceStride) return trainDecayStride<RowClamp::Discrete, Quad4>(s, weights, traces, live, count);
    return trainDecayStride<RowClamp::Any, Quad4>(s, weights, traces, live, count);
}

}  // namespace verve::core
