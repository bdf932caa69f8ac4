// Kernels for any CPU: Eigen's fixed-size arrays map onto the SIMD the build targets
// (SSE2 on x86-64, NEON on ARM64).
#include <Eigen/Core>

#include <algorithm>

#include "core/kernel_loops.hpp"
#include "core/kernels.hpp"

namespace verve::core {
namespace {

using Lanes = Eigen::Array<float, kScanLanes, 1>;
using Quad = Eigen::Array4f;

std::size_t scan(const ScanParams& p, const float* centres, const std::uint32_t* features, std::uint32_t firstFeature,
                 std::size_t count, ActiveFeature* out, bool& nearOne) {
    std::size_t n = 0;
    const float* block = centres;
    for (std::size_t first = 0; first < count; first += kScanLanes) {
        askAhead(p.ahead, kAheadPerBlock);
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
            const auto i = static_cast<std::uint32_t>(first + l);
            out[n] = ActiveFeature{features != nullptr ? features[i] : firstFeature + i, activation[l]};
            n += d2[l] < p.cutoff2;
            nearOne |= d2[l] < p.width2;
        }
    }
    return n;
}

void boxesWithin(const ScanParams& p, const float* boxes, std::size_t count, float reach2, std::uint8_t* masks) {
    for (std::size_t first = 0; first < count; first += kScanLanes, ++masks) {
        Lanes d2 = Lanes::Zero();
        for (std::uint32_t d = 0; d < p.dims; ++d, boxes += 2 * kScanLanes) {
            const Eigen::Map<const Lanes> lo(boxes), hi(boxes + kScanLanes);
            auto gap = [&](float at) { return (lo - at).max(at - hi).max(0.0f); };
            Lanes g = gap(p.point[d]);
            if (p.circular[d]) g = g.min(gap(p.point[d] - 2.0f)).min(gap(p.point[d] + 2.0f));
            d2 += g.square();
        }
        const std::size_t lanes = std::min<std::size_t>(kScanLanes, count - first);
        std::uint8_t mask = 0;
        for (std::size_t l = 0; l < lanes; ++l) mask |= static_cast<std::uint8_t>((d2[l] <= reach2 ? 1u : 0u) << l);
        *masks = mask;
    }
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
             std::uint32_t columns, float* sums, PrefetchQueue* ahead) {
    std::uint32_t c = 0;
    for (; c + 4 <= columns; c += 4) {  // four columns at once, two features in flight
        Quad a = Quad::Zero(), b = Quad::Zero();
        std::size_t i = 0;
        for (; i + 2 <= n; i += 2) {
            askAhead(ahead, (i & 2) != 0 ? kAheadPerBlock : 0);  // per 4 rows
            a += Eigen::Map<const Quad>(weights + std::size_t(phi[i].index) * stride + c) * phi[i].activation;
            b += Eigen::Map<const Quad>(weights + std::size_t(phi[i + 1].index) * stride + c) * phi[i + 1].activation;
        }
        if (i < n) a += Eigen::Map<const Quad>(weights + std::size_t(phi[i].index) * stride + c) * phi[i].activation;
        Eigen::Map<Quad>(sums + c) = a + b;
    }
    for (; c < columns; ++c) sums[c] = columnSum(weights, stride, phi, n, c);
}

// w += step * e, then e *= scale, for 4 trace components.
struct Quad4 {
    static void train(float* w, float* e, const float* step, float scale) {
        Eigen::Map<Quad> ek(e);
        Eigen::Map<Quad>(w) += Eigen::Map<const Quad>(step) * ek;
        ek *= scale;
    }
    // The same, each weight then within [lo, hi] as std::clamp puts it: min(max(w, lo), hi).
    static void trainClamped(float* w, float* e, const float* step, float scale, const float* lo, const float* hi) {
        train(w, e, step, scale);
        for (int j = 0; j < 4; ++j) {
            const float raised = w[j] < lo[j] ? lo[j] : w[j];
            w[j] = hi[j] < raised ? hi[j] : raised;
        }
    }
};

std::size_t strongFeatures(const ActiveFeature* phi, std::size_t n, float threshold, std::uint32_t below, ActiveFeature* out) {
    return strongFeaturesFrom<Quad4>(phi, 0, n, threshold, below, out, 0);
}

}  // namespace

const Kernels& portableKernels() {
    static const Kernels k{"portable", scan, boxesWithin, rowSums, strongFeatures, trainDecay<Quad4>};
    return k;
}

}  // namespace verve::core
