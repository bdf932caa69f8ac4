// Loop shapes shared by the kernel sets (kernels_portable.cpp, kernels_avx2.cpp). Each set
// instantiates them with its own 4-wide step, a type from its anonymous namespace, so every
// instantiation stays private to its file: the AVX2 one can never be handed to other code.
#pragma once
#include <cstddef>
#include <cstdint>

#include "core/kernels.hpp"
#include "core/prefetch.hpp"

namespace verve::core {

// S trace components, known at compile time for the common action counts (0: s.traceStride).
// Quad4::train(w, e, step, scale) does, for 4 components, w += step * e, then e *= scale.
template <std::uint32_t S, typename Quad4>
std::uint32_t trainDecayRows(const TraceStep& s, float* __restrict weights, float* __restrict traces,
                             std::uint32_t* __restrict live, std::uint32_t count) {
    const std::uint32_t stride = S != 0 ? S : s.traceStride;
    const std::size_t weightStride = s.weightStride;
    const float* __restrict step = s.step;
    const float decay = s.decay, threshold = s.threshold;
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
        for (; k + 4 <= stride; k += 4) Quad4::train(w + k, e + k, step + k, scale);
        for (; k < stride; ++k) {
            w[k] += step[k] * e[k];
            e[k] *= scale;
        }
        live[kept] = feature;
        kept += keep;
    }
    return kept;
}

// Kernels::trainDecay for a kernel set.
template <typename Quad4>
std::uint32_t trainDecay(const TraceStep& s, float* weights, float* traces, std::uint32_t* live,
                             std::uint32_t count) {
    switch (s.traceStride) {  // 1 + actions
        case 3: return trainDecayRows<3, Quad4>(s, weights, traces, live, count);
        case 4: return trainDecayRows<4, Quad4>(s, weights, traces, live, count);
        case 5: return trainDecayRows<5, Quad4>(s, weights, traces, live, count);
        case 6: return trainDecayRows<6, Quad4>(s, weights, traces, live, count);
        case 9: return trainDecayRows<9, Quad4>(s, weights, traces, live, count);
        default: return trainDecayRows<0, Quad4>(s, weights, traces, live, count);
    }
}

}  // namespace verve::core
