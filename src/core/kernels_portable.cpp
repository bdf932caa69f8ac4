// Kernels for any CPU: Eigen's fixed-size arrays map onto the SIMD the build targets
// (SSE2 on x86-64, NEON on ARM64).
#include <Eigen/Core>

#include <algorithm>

#include "core/kernels.hpp"

namespace verve::core {
namespace {

using Lanes = Eigen::Array<float, kScanLanes, 1>;
using Quad = Eigen::Array4f;

std::size_t scan(const ScanParams& p, const float* centres, const std::uint32_t* features, std::size_t count,
                 ActiveFeature* out, bool& nearOne) {
    std::size_t n = 0;
    const float* block = centres;
    for (std::size_t first = 0; first < count; first += kScanLanes) {
        Lanes d2 = Lanes::Zero();
        for (std::uint32_t d = 0; d < p.dims; ++d, block += kScanLanes) {
            Lanes diff = p.point[d] - Eigen::Map<const Lanes>(block);
            if (p.circular[d]) {  // the shorter way round: -1 and 1 meet
                diff = (diff > 1.0f).select(diff - 2.0f, (diff < -1.0f).select(diff + 2.0f, diff));
            }
            d2 += diff.square();
        }
        const Lanes activation = (d2 * p.negInv2Sigma2).exp();
        // Branch-free: every candidate is written and kept only within the cutoff
        // (about half are, so a branch would mispredict constantly).
        const std::size_t lanes = std::min<std::size_t>(kScanLanes, count - first);
        for (std::size_t l = 0; l < lanes; ++l) {
            out[n] = ActiveFeature{features[first + l], activation[l]};
            n += d2[l] < p.cutoff2;
            nearOne |= d2[l] < p.width2;
        }
    }
    return n;
}

// Four running sums of one column over the features: independent chains, so the adds overlap.
float columnSum(const float* weights, std::uint32_t stride, const ActiveFeature* phi, std::size_t n,
                std::uint32_t column) {
    float s[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        for (std::size_t j = 0; j < 4; ++j) {
            s[j] += weights[std::size_t(phi[i + j].index) * stride + column] * phi[i + j].activation;
        }
    }
    for (; i < n; ++i) s[0] += weights[std::size_t(phi[i].index) * stride + column] * phi[i].activation;
    return (s[0] + s[1]) + (s[2] + s[3]);
}

void rowSums(const float* weights, std::uint32_t stride, const ActiveFeature* phi, std::size_t n,
             std::uint32_t columns, float* sums) {
    std::uint32_t c = 0;
    for (; c + 4 <= columns; c += 4) {  // four columns at once, two features in flight
        Quad a = Quad::Zero(), b = Quad::Zero();
        std::size_t i = 0;
        for (; i + 2 <= n; i += 2) {
            a += Eigen::Map<const Quad>(weights + std::size_t(phi[i].index) * stride + c) * phi[i].activation;
            b += Eigen::Map<const Quad>(weights + std::size_t(phi[i + 1].index) * stride + c) * phi[i + 1].activation;
        }
        if (i < n) a += Eigen::Map<const Quad>(weights + std::size_t(phi[i].index) * stride + c) * phi[i].activation;
        Eigen::Map<Quad>(sums + c) = a + b;
    }
    for (; c < columns; ++c) sums[c] = columnSum(weights, stride, phi, n, c);
}

// S trace components, known at compile time for the common action counts (0: s.traceStride).
template <std::uint32_t S>
std::uint32_t trainDecayRows(const TraceStep& s, float* __restrict weights, float* __restrict traces,
                             std::uint32_t* __restrict live, std::uint32_t count) {
    const std::uint32_t stride = S != 0 ? S : s.traceStride;
    const std::size_t weightStride = s.weightStride;
    const float* __restrict step = s.step;
    const float decay = s.decay, threshold = s.threshold;
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t feature = live[i];
        float* __restrict w = weights + feature * weightStride;
        float* __restrict e = traces + std::size_t(feature) * stride;
        // The value component decides whether the trace stays live; a dropped one is zeroed,
        // branch-free, and the live list is compacted in order.
        const bool keep = e[0] * decay >= threshold;
        const float scaled = keep ? decay : 0.0f;
        std::uint32_t k = 0;
        for (; k + 4 <= stride; k += 4) {
            Eigen::Map<Quad> ek(e + k);
            Eigen::Map<Quad>(w + k) += Eigen::Map<const Quad>(step + k) * ek;
            ek *= scaled;
        }
        for (; k < stride; ++k) {
            w[k] += step[k] * e[k];
            e[k] *= scaled;
        }
        live[kept] = feature;
        kept += keep;
    }
    return kept;
}

std::uint32_t trainDecay(const TraceStep& s, float* weights, float* traces, std::uint32_t* live, std::uint32_t count) {
    switch (s.traceStride) {  // 1 + actions
        case 3: return trainDecayRows<3>(s, weights, traces, live, count);
        case 4: return trainDecayRows<4>(s, weights, traces, live, count);
        case 5: return trainDecayRows<5>(s, weights, traces, live, count);
        case 6: return trainDecayRows<6>(s, weights, traces, live, count);
        case 9: return trainDecayRows<9>(s, weights, traces, live, count);
        default: return trainDecayRows<0>(s, weights, traces, live, count);
    }
}

}  // namespace

const Kernels& portableKernels() {
    static const Kernels k{"portable", scan, rowSums, trainDecay};
    return k;
}

}  // namespace verve::core
