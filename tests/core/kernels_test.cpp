// Every kernel set this CPU runs (portable, and AVX2 + FMA where supported) against a plain
// double-precision reference: the same features in the same order, values within float rounding.
#include "core/kernels.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/rng.hpp"

using verve::core::ActiveFeature;
using verve::core::Kernels;
using verve::core::kScanLanes;
using verve::core::Rng;
using verve::core::ScanParams;
using verve::core::TraceStep;

namespace {

std::vector<const Kernels*> kernelSets() {
    std::vector<const Kernels*> sets{&verve::core::portableKernels()};
    if (verve::core::avx2Kernels() != nullptr) sets.push_back(verve::core::avx2Kernels());
    return sets;
}

float uniform(Rng& rng, float lo, float hi) { return lo + (hi - lo) * rng.uniform(); }

struct ScanCase {
    std::uint32_t dims;
    std::size_t count;
    std::vector<std::uint8_t> circular;
    std::vector<float> point, centres;  // centres: [rbf][dim] (the reference's layout)
    std::vector<std::uint32_t> features;
};

ScanCase randomCase(Rng& rng, std::uint32_t dims, std::size_t count) {
    ScanCase c{dims, count, {}, {}, {}, {}};
    for (std::uint32_t d = 0; d < dims; ++d) {
        c.circular.push_back(d % 2 == 1 ? 1 : 0);
        c.point.push_back(uniform(rng, -1.0f, 1.0f));
    }
    for (std::size_t i = 0; i < count * dims; ++i) c.centres.push_back(uniform(rng, -1.0f, 1.0f));
    for (std::size_t i = 0; i < count; ++i) c.features.push_back(static_cast<std::uint32_t>(1000 + 7 * i));
    return c;
}

// [block][dim][lane], the last block padded with zeros.
std::vector<float> blocked(const ScanCase& c) {
    const std::size_t blocks = (c.count + kScanLanes - 1) / kScanLanes;
    std::vector<float> out(blocks * c.dims * kScanLanes, 0.0f);
    for (std::size_t i = 0; i < c.count; ++i) {
        for (std::uint32_t d = 0; d < c.dims; ++d) {
            out[(i / kScanLanes) * c.dims * kScanLanes + d * kScanLanes + i % kScanLanes] = c.centres[i * c.dims + d];
        }
    }
    return out;
}

}  // namespace

TEST(Kernels, ScanFindsWhatADoublePrecisionScanFinds) {
    Rng rng(7);
    const float sigma = 0.25f;
    for (const Kernels* k : kernelSets()) {
        SCOPED_TRACE(k->name);
        for (std::uint32_t dims : {1u, 2u, 4u, 5u}) {
            for (std::size_t count : {1u, 7u, 8u, 9u, 16u, 61u}) {
                const ScanCase c = randomCase(rng, dims, count);
                ScanParams p;
                p.point = c.point.data();
                p.circular = c.circular.data();
                p.dims = dims;
                p.cutoff2 = 16.0f * sigma * sigma;
                p.width2 = sigma * sigma;
                p.negInv2Sigma2 = -1.0f / (2.0f * sigma * sigma);
                const std::vector<float> centres = blocked(c);
                std::vector<ActiveFeature> out((count + kScanLanes - 1) / kScanLanes * kScanLanes);
                bool near = false;
                // Odd counts name the features, even ones count them from 500 (a cell numbered in order).
                const bool counted = count % 2 == 0;
                const std::size_t n = k->scan(p, centres.data(), counted ? nullptr : c.features.data(), 500, count,
                                              out.data(), near);

                std::vector<ActiveFeature> expected;
                bool expectedNear = false;
                for (std::size_t i = 0; i < count; ++i) {
                    double d2 = 0.0;
                    for (std::uint32_t d = 0; d < dims; ++d) {
                        double diff = double(c.point[d]) - double(c.centres[i * dims + d]);
                        if (c.circular[d] && diff > 1.0) diff -= 2.0;
                        if (c.circular[d] && diff < -1.0) diff += 2.0;
                        d2 += diff * diff;
                    }
                    const std::uint32_t index = counted ? 500 + static_cast<std::uint32_t>(i) : c.features[i];
                    if (d2 < p.cutoff2) expected.emplace_back(index, float(std::exp(-d2 / (2.0 * sigma * sigma))));
                    expectedNear |= d2 < p.width2;
                }
                ASSERT_EQ(n, expected.size()) << dims << " dims, " << count << " RBFs";
                EXPECT_EQ(near, expectedNear);
                for (std::size_t i = 0; i < n; ++i) {
                    EXPECT_EQ(out[i].index, expected[i].index);
                    EXPECT_NEAR(out[i].activation, expected[i].activation, 1e-6f * expected[i].activation + 1e-9f);
                }
            }
        }
    }
}

// Boxes in groups of 8, [group][dim][lowest lanes, highest lanes]: a box is within reach when its
// squared distance to the point (the shorter way on circular sensors) is at most reach2.
TEST(Kernels, BoxesWithinMatchesADoublePrecisionBoxDistance) {
    Rng rng(5);
    for (const Kernels* k : kernelSets()) {
        SCOPED_TRACE(k->name);
        for (std::uint32_t dims : {1u, 2u, 4u}) {
            for (std::size_t count : {1u, 8u, 13u, 70u}) {
                const ScanCase c = randomCase(rng, dims, count);
                ScanParams p;
                p.point = c.point.data();
                p.circular = c.circular.data();
                p.dims = dims;
                const std::size_t groups = (count + kScanLanes - 1) / kScanLanes;
                std::vector<float> boxes(groups * dims * 2 * kScanLanes, 0.0f);
                std::vector<double> lo(count * dims), hi(count * dims);
                for (std::size_t b = 0; b < count; ++b) {
                    for (std::uint32_t d = 0; d < dims; ++d) {
                        const float x = uniform(rng, -1.0f, 1.0f), w = uniform(rng, 0.0f, 0.5f);
                        float* at = boxes.data() + (b / kScanLanes) * dims * 2 * kScanLanes + d * 2 * kScanLanes + b % kScanLanes;
                        at[0] = x;
                        at[kScanLanes] = x + w;
                        lo[b * dims + d] = x;
                        hi[b * dims + d] = double(x) + double(w);
                    }
                }
                const float reach2 = 0.3f;
                std::vector<std::uint8_t> masks(groups, 0xff);
                k->boxesWithin(p, boxes.data(), count, reach2, masks.data());
                for (std::size_t b = 0; b < groups * kScanLanes; ++b) {
                    const bool within = ((masks[b / 8] >> (b % 8)) & 1u) != 0;
                    if (b >= count) {
                        EXPECT_FALSE(within) << "box " << b << " does not exist";
                        continue;
                    }
                    double d2 = 0.0;
                    for (std::uint32_t d = 0; d < dims; ++d) {
                        auto gap = [&](double x) { return std::max(0.0, std::max(lo[b * dims + d] - x, x - hi[b * dims + d])); };
                        double g = gap(c.point[d]);
                        if (c.circular[d]) g = std::min(g, std::min(gap(c.point[d] - 2.0), gap(c.point[d] + 2.0)));
                        d2 += g * g;
                    }
                    if (std::fabs(d2 - reach2) > 1e-5) EXPECT_EQ(within, d2 <= reach2) << "box " << b << ", " << dims << " dims";
                }
            }
        }
    }
}

TEST(Kernels, RowSumsAddEveryColumnOfEveryFeature) {
    Rng rng(11);
    for (const Kernels* k : kernelSets()) {
        SCOPED_TRACE(k->name);
        for (std::uint32_t stride : {1u, 2u, 4u, 5u, 8u, 11u, 19u}) {
            for (std::size_t n : {0u, 1u, 3u, 4u, 9u, 130u}) {
                std::vector<float> weights(64 * stride);
                for (auto& w : weights) w = uniform(rng, -2.0f, 2.0f);
                std::vector<ActiveFeature> phi;
                for (std::size_t i = 0; i < n; ++i) phi.emplace_back(static_cast<std::uint32_t>(rng.below(64)), rng.uniform());
                for (std::uint32_t columns = 1; columns <= stride; ++columns) {
                    std::vector<float> sums(columns, -99.0f);
                    k->rowSums(weights.data(), stride, phi.data(), n, columns, sums.data(), nullptr);
                    for (std::uint32_t c = 0; c < columns; ++c) {
                        double expected = 0.0;
                        for (const auto& f : phi) expected += double(weights[f.index * stride + c]) * f.activation;
                        EXPECT_NEAR(sums[c], expected, 1e-5 * (1.0 + double(n))) << "stride " << stride << " column " << c;
                    }
                }
            }
        }
    }
}

TEST(Kernels, TrainDecayUpdatesLiveRowsAndDropsFadedTracesInOrder) {
    Rng rng(13);
    for (const Kernels* k : kernelSets()) {
        SCOPED_TRACE(k->name);
        for (std::uint32_t traceStride : {2u, 3u, 4u, 5u, 9u}) {
            const std::uint32_t weightStride = traceStride + 3;  // model columns after the traces
            const std::uint32_t features = 50;
            std::vector<float> weights(features * weightStride), traces(features * traceStride, 0.0f), step(traceStride);
            for (auto& w : weights) w = uniform(rng, -1.0f, 1.0f);
            for (auto& s : step) s = uniform(rng, -0.5f, 0.5f);
            std::vector<std::uint32_t> live;
            for (std::uint32_t f = 0; f < features; f += 3) {
                live.push_back(f);
                for (std::uint32_t c = 0; c < traceStride; ++c) traces[f * traceStride + c] = uniform(rng, 0.0f, 0.05f);
            }
            const std::vector<float> w0 = weights, e0 = traces;
            TraceStep s;
            s.step = step.data();
            s.traceStride = traceStride;
            s.weightStride = weightStride;
            s.decay = 0.5f;
            s.threshold = 0.01f;
            std::vector<std::uint32_t> liveOut = live;
            const std::uint32_t kept = k->trainDecay(s, weights.data(), traces.data(), liveOut.data(),
                                                     static_cast<std::uint32_t>(live.size()));

            std::vector<std::uint32_t> expectedLive;
            for (std::uint32_t f = 0; f < features; ++f) {
                const bool isLive = f % 3 == 0;
                const bool keeps = isLive && e0[f * traceStride] * 0.5f >= s.threshold;
                if (keeps) expectedLive.push_back(f);
                for (std::uint32_t c = 0; c < weightStride; ++c) {
                    const float trained = c < traceStride && isLive ? step[c] * e0[f * traceStride + c] : 0.0f;
                    EXPECT_NEAR(weights[f * weightStride + c], w0[f * weightStride + c] + trained, 1e-6f);
                }
                for (std::uint32_t c = 0; c < traceStride; ++c) {
                    EXPECT_FLOAT_EQ(traces[f * traceStride + c], keeps ? e0[f * traceStride + c] * 0.5f : 0.0f);
                }
            }
            ASSERT_EQ(kept, expectedLive.size());
            for (std::uint32_t i = 0; i < kept; ++i) EXPECT_EQ(liveOut[i], expectedLive[i]);
        }
    }
}

TEST(Kernels, TrainDecayClampsEachTrainedRowsActorColumns) {
    Rng rng(17);
    for (const Kernels* k : kernelSets()) {
        SCOPED_TRACE(k->name);
        // Discrete columns only (the stride's own loop), and discrete then continuous ones.
        for (std::uint32_t continuous : {0u, 2u}) {
            for (bool clampsDiscrete : {true, false}) {
                const std::uint32_t discrete = 3, traceStride = 1 + discrete + continuous, weightStride = traceStride + 2;
                const std::uint32_t features = 40;
                std::vector<float> weights(features * weightStride), traces(features * traceStride, 0.0f), step(traceStride);
                for (auto& w : weights) w = uniform(rng, -3.0f, 3.0f);
                for (auto& x : step) x = uniform(rng, -20.0f, 20.0f);
                std::vector<std::uint32_t> live;
                for (std::uint32_t f = 0; f < features; f += 2) {
                    live.push_back(f);
                    for (std::uint32_t c = 0; c < traceStride; ++c) traces[f * traceStride + c] = uniform(rng, 0.0f, 0.2f);
                }
                const std::vector<float> w0 = weights, e0 = traces;
                TraceStep s;
                s.step = step.data();
                s.traceStride = traceStride;
                s.weightStride = weightStride;
                s.decay = 0.5f;
                s.threshold = 0.01f;
                s.clampsDiscrete = clampsDiscrete;
                s.discreteColumns = discrete;
                s.low = -1.0f;
                s.high = 0.5f;
                s.boundedColumns = continuous;
                s.bound = 2.0f;
                k->trainDecay(s, weights.data(), traces.data(), live.data(), static_cast<std::uint32_t>(live.size()));
                for (std::uint32_t f = 0; f < features; ++f) {
                    for (std::uint32_t c = 0; c < weightStride; ++c) {
                        const bool trained = f % 2 == 0 && c < traceStride;
                        float expected = w0[f * weightStride + c] + (trained ? step[c] * e0[f * traceStride + c] : 0.0f);
                        if (trained && c >= 1 && c <= discrete && clampsDiscrete) expected = std::clamp(expected, -1.0f, 0.5f);
                        if (trained && c > discrete) expected = std::clamp(expected, -2.0f, 2.0f);
                        EXPECT_NEAR(weights[f * weightStride + c], expected, 1e-5f) << "feature " << f << " column " << c;
                    }
                }
            }
        }
    }
}

TEST(Kernels, StrongFeaturesKeepThoseAtTheThresholdBelowTheIndexLimitInOrder) {
    Rng rng(19);
    for (const Kernels* k : kernelSets()) {
        SCOPED_TRACE(k->name);
        for (std::size_t n : {0u, 1u, 3u, 4u, 5u, 17u, 64u}) {
            std::vector<ActiveFeature> phi(n);
            for (std::size_t i = 0; i < n; ++i) {
                // Activations on both sides of the threshold and on it; indices on both sides of the limit,
                // with the top bit set too (the limit is compared unsigned).
                const float a = i % 5 == 0 ? 0.01f : uniform(rng, 0.0f, 0.03f);
                const std::uint32_t index = i % 7 == 3 ? 0x80000000u + static_cast<std::uint32_t>(i) : static_cast<std::uint32_t>(rng.below(200));
                phi[i] = ActiveFeature(index, a);
            }
            for (std::uint32_t below : {100u, 0x80000004u, UINT32_MAX}) {
                std::vector<ActiveFeature> out(n), expected;
                for (const ActiveFeature& f : phi) {
                    if (f.activation >= 0.01f && f.index < below) expected.push_back(f);
                }
                const std::size_t count = k->strongFeatures(phi.data(), n, 0.01f, below, out.data());
                ASSERT_EQ(count, expected.size());
                for (std::size_t i = 0; i < count; ++i) {
                    EXPECT_EQ(out[i].index, expected[i].index);
                    EXPECT_EQ(out[i].activation, expected[i].activation);
                }
            }
        }
    }
}

TEST(Kernels, TheChosenSetIsTheFastestThisCpuRuns) {
    const Kernels* avx2 = verve::core::avx2Kernels();
    EXPECT_EQ(&verve::core::kernels(), avx2 != nullptr ? avx2 : &verve::core::portableKernels());
}
