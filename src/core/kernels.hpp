// The hot loops of one update, behind a table chosen once for the CPU at hand: the library is
// built for any x86-64 (SSE2), and a CPU with AVX2 and FMA runs 8-wide kernels instead.
// Implementations: kernels_portable.cpp (any CPU), kernels_avx2.cpp (x86-64 with AVX2 + FMA);
// kernels.cpp chooses. The kernels take raw pointers only, so the AVX2 file instantiates no
// template that another file could share (its code would then run on CPUs without AVX2).
#pragma once
#include <cstddef>
#include <cstdint>

#include "core/active_feature.hpp"
#include "core/prefetch.hpp"

namespace verve::core {

// RBFs of a scan are stored in blocks of kScanLanes, dimension by dimension: [block][dim][lane].
constexpr std::uint32_t kScanLanes = 8;
// Cache lines of a batch's next agent asked for (PrefetchQueue) per block of kScanLanes RBFs
// scanned, per 4 rows summed, and per live trace trained: about as many as a cart-pole-shaped
// update reads, spread over it.
constexpr unsigned kAheadPerBlock = 3;

struct ScanParams {
    const float* point = nullptr;            // the input, dims values in [-1, 1]
    const std::uint8_t* circular = nullptr;  // per dimension: 1 when -1 and 1 meet
    std::uint32_t dims = 0;
    float cutoff2 = 0.0f;        // squared distance beyond which an activation counts as zero
    float width2 = 0.0f;         // squared width: an RBF this close means no new one is needed
    float negInv2Sigma2 = 0.0f;  // activation = exp(d2 * negInv2Sigma2)
    PrefetchQueue* ahead = nullptr;  // a batch's next agent: asked for as the scan goes (prefetch.hpp)
};

// One step of TD learning over the live traces (td_learner.hpp).
struct TraceStep {
    const float* step = nullptr;  // eta * delta per trace component
    std::uint32_t traceStride = 0;  // components per trace; they line up with a weight row's first ones
    std::uint32_t weightStride = 0;
    float decay = 0.0f;
    float threshold = 0.0f;  // a trace whose value component falls below it is dropped
    PrefetchQueue* ahead = nullptr;  // as in ScanParams
    // Each trained row's actor weights kept in range as soon as it is trained (while in cache, and
    // no second pass over the scattered rows): when `clampsDiscrete`, the `discreteColumns` columns
    // from 1 on within [low, high]; always the `boundedColumns` continuous ones after them within
    // +-bound.
    bool clampsDiscrete = false;
    std::uint32_t discreteColumns = 0;
    float low = 0.0f, high = 0.0f;
    std::uint32_t boundedColumns = 0;
    float bound = 0.0f;
};

struct Kernels {
    const char* name;
    // Writes the `count` RBFs of `centres` (blocks as above; `features` are their indices, or null
    // when they are firstFeature, firstFeature + 1, ...) that lie within the cutoff to `out`, in
    // order, and returns how many. `out` needs room for `count` rounded up to kScanLanes. Sets
    // `nearOne` when one lies within a width.
    std::size_t (*scan)(const ScanParams& p, const float* centres, const std::uint32_t* features,
                        std::uint32_t firstFeature, std::size_t count, ActiveFeature* out, bool& nearOne);
    // For `count` boxes stored in groups of kScanLanes, [group][dimension][lowest lanes, highest
    // lanes], sets bit b % kScanLanes of masks[b / kScanLanes] when box b lies within squared
    // distance `reach2` of the point (the shorter way on circular sensors), and clears the others.
    void (*boxesWithin)(const ScanParams& p, const float* boxes, std::size_t count, float reach2, std::uint8_t* masks);
    // sums[k] = sum over phi of row(phi.index)[k] * phi.activation, for k < columns <= stride.
    void (*rowSums)(const float* weights, std::uint32_t stride, const ActiveFeature* phi, std::size_t n,
                    std::uint32_t columns, float* sums, PrefetchQueue* ahead);
    // Writes the features of phi[0..n) active at `threshold` or more whose index is below `below`
    // to `out` (room for n), in order, and returns how many: those that mark a trace.
    std::size_t (*strongFeatures)(const ActiveFeature* phi, std::size_t n, float threshold, std::uint32_t below,
                                  ActiveFeature* out);
    // For each live feature: w += step * e (then the row's clamps, TraceStep), then e *= decay;
    // drops (zeroes) the traces that fall below the threshold and compacts `live` in order.
    // Returns how many stay live.
    std::uint32_t (*trainDecay)(const TraceStep& s, float* weights, float* traces, std::uint32_t* live,
                                std::uint32_t count);
};

const Kernels& kernels();          // the fastest this CPU runs, chosen on first use
const Kernels& portableKernels();  // any CPU
const Kernels* avx2Kernels();      // null unless built in and supported by this CPU

}  // namespace verve::core
