#include "core/state_representation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "core/rng.hpp"

using verve::AgentDescriptor;
using verve::core::ActiveFeature;
using verve::core::StateRepresentation;

namespace {

// One lattice: these tests count its RBFs (the fine one beside it: fine_lattice_test.cpp).
AgentDescriptor continuous1D(std::uint32_t resolution, bool circular = false) {
    AgentDescriptor d;
    d.addContinuousSensor(circular);
    d.resolution = resolution;
    d.adaptation &= ~verve::Adaptation::FineLattice;
    return d;
}

std::uint64_t keyOf(const StateRepresentation& rep, std::uint32_t feature) {
    std::vector<std::uint64_t> keys;
    std::vector<float> centres;
    rep.features(keys, centres);
    return keys.at(feature);
}

std::vector<float> centreOf(const StateRepresentation& rep, std::uint32_t feature) {
    std::vector<std::uint64_t> keys;
    std::vector<float> centres;
    rep.features(keys, centres);
    const std::size_t n = rep.numContinuous();
    return std::vector<float>(centres.begin() + feature * n, centres.begin() + (feature + 1) * n);
}

float activationOf(const std::vector<ActiveFeature>& phi, std::uint32_t index) {
    for (const auto& f : phi) if (f.index == index) return f.activation;
    return 0.0f;
}

}  // namespace

TEST(StateRepresentation, DiscreteOnlyHasOneFullyActiveFeaturePerCombination) {
    AgentDescriptor d;
    d.addDiscreteSensor(3).addDiscreteSensor(4);
    StateRepresentation rep(d);
    std::vector<ActiveFeature> phi;
    const std::int32_t a[] = {2, 1};
    EXPECT_EQ(rep.activate(a, nullptr, true, phi), 1u);
    ASSERT_EQ(phi.size(), 1u);
    EXPECT_EQ(phi[0].activation, 1.0f);
    EXPECT_EQ(keyOf(rep, phi[0].index), 2u * 4u + 1u);  // mixed radix
    EXPECT_EQ(rep.activate(a, nullptr, true, phi), 0u);  // seen before: no new feature
    ASSERT_EQ(phi.size(), 1u);
    const std::int32_t b[] = {2, 2};
    rep.activate(b, nullptr, true, phi);  // other combinations never share features
    ASSERT_EQ(phi.size(), 1u);
    EXPECT_EQ(phi[0].index, 1u);
    EXPECT_EQ(rep.activationSum(), 1.0f);
}

TEST(StateRepresentation, GaussianActivationWithWidthTwoOverResolution) {
    StateRepresentation rep(continuous1D(10));  // sigma = 0.2
    std::vector<ActiveFeature> phi;
    const float x0 = 0.0f;
    rep.activate(nullptr, &x0, true, phi);
    const float x1 = 0.1f;  // within sigma of the first RBF: no new RBF
    EXPECT_EQ(rep.activate(nullptr, &x1, true, phi), 0u);
    ASSERT_EQ(phi.size(), 1u);
    EXPECT_NEAR(phi[0].activation, std::exp(-0.01f / (2 * 0.04f)), 1e-6f);  // e^(-d^2 / 2 sigma^2)
    EXPECT_NEAR(rep.activationSum(), 2.5f, 1e-6f);
}

TEST(StateRepresentation, AllocatesOnlyWhenNoRbfWithinOneWidth) {
    StateRepresentation rep(continuous1D(10));
    std::vector<ActiveFeature> phi;
    const float a = 0.0f, b = 0.19f, c = 0.21f;
    rep.activate(nullptr, &a, true, phi);
    EXPECT_EQ(rep.activate(nullptr, &b, true, phi), 0u);
    EXPECT_EQ(rep.activate(nullptr, &c, true, phi), 1u);  // 0.21 > sigma from 0: a new RBF centred on it
    EXPECT_EQ(rep.featureCount(), 2u);
    EXPECT_EQ(centreOf(rep, 1)[0], 0.21f);
    ASSERT_EQ(phi.size(), 2u);
    EXPECT_NEAR(activationOf(phi, 0), std::exp(-0.0441f / 0.08f), 1e-6f);
    EXPECT_EQ(activationOf(phi, 1), 1.0f);
}

TEST(StateRepresentation, IgnoresActivationsBeyondFourWidths) {
    StateRepresentation rep(continuous1D(10));
    std::vector<ActiveFeature> phi;
    const float a = -0.5f, near = 0.29f, far = 0.31f;  // 4 sigma = 0.8
    rep.activate(nullptr, &a, true, phi);
    rep.activate(nullptr, &near, false, phi);
    EXPECT_EQ(phi.size(), 1u);
    rep.activate(nullptr, &far, false, phi);
    EXPECT_TRUE(phi.empty());
}

TEST(StateRepresentation, CircularSensorsWrapAcrossTheSeam) {
    StateRepresentation rep(continuous1D(10, true));
    std::vector<ActiveFeature> phi;
    const float a = 0.95f, b = -0.95f;  // 0.1 apart the short way round
    rep.activate(nullptr, &a, true, phi);
    EXPECT_EQ(rep.activate(nullptr, &b, true, phi), 0u);
    ASSERT_EQ(phi.size(), 1u);
    EXPECT_NEAR(phi[0].activation, std::exp(-0.01f / 0.08f), 1e-5f);

    StateRepresentation flat(continuous1D(10, false));
    flat.activate(nullptr, &a, true, phi);
    EXPECT_EQ(flat.activate(nullptr, &b, true, phi), 1u);  // 1.9 apart: no wrap
}

TEST(StateRepresentation, DiscreteCombinationsHaveSeparateRbfArrays) {
    AgentDescriptor d = continuous1D(10);
    d.addDiscreteSensor(2);
    StateRepresentation rep(d);
    std::vector<ActiveFeature> phi;
    const float x = 0.0f;
    const std::int32_t day = 0, night = 1;
    rep.activate(&day, &x, true, phi);
    EXPECT_EQ(rep.activate(&night, &x, true, phi), 1u);  // same point, other array
    ASSERT_EQ(phi.size(), 1u);
    EXPECT_EQ(phi[0].index, 1u);
}

TEST(StateRepresentation, FullAllocationBuildsTheLattice) {
    AgentDescriptor d = continuous1D(4);
    d.addContinuousSensor();
    d.addDiscreteSensor(3);
    d.allocation = verve::RbfAllocation::Full;
    StateRepresentation rep(d);
    EXPECT_EQ(rep.featureCount(), 3u * 4u * 4u);
    EXPECT_FLOAT_EQ(centreOf(rep, 0)[0], -0.75f);  // -1 + (0 + 0.5) * sigma, sigma = 0.5
    EXPECT_FLOAT_EQ(centreOf(rep, 1)[0], -0.25f);
    std::vector<ActiveFeature> phi;
    const float x[] = {0.9f, -0.9f};
    const std::int32_t k = 2;
    EXPECT_EQ(rep.activate(&k, x, true, phi), 0u);  // full lattices never grow
}

// The spatial index must find exactly what a scan of every RBF finds: `queries` random points
// of `dims` sensors, of which those flagged in `circular` wrap.
static void expectIndexMatchesBruteForce(const StateRepresentation& rep, std::uint32_t dims, const std::vector<bool>& circular,
                                         float sigma, verve::core::Rng& rng, int queries) {
    std::vector<std::uint64_t> keys;
    std::vector<float> centres;
    rep.features(keys, centres);
    std::vector<ActiveFeature> phi;
    std::vector<float> p(dims);
    for (int q = 0; q < queries; ++q) {
        for (float& x : p) x = rng.uniform() * 2 - 1;
        rep.find(nullptr, p.data(), phi);
        std::size_t expected = 0;
        for (std::uint32_t f = 0; f < rep.featureCount(); ++f) {
            float d2 = 0;
            for (std::uint32_t k = 0; k < dims; ++k) {
                float diff = p[k] - centres[std::size_t(f) * dims + k];
                if (circular[k]) { if (diff > 1) diff -= 2; else if (diff < -1) diff += 2; }
                d2 += diff * diff;
            }
            if (d2 >= 16 * sigma * sigma) continue;
            ++expected;
            EXPECT_NEAR(activationOf(phi, f), std::exp(-d2 / (2 * sigma * sigma)), 1e-5f);
        }
        EXPECT_EQ(phi.size(), expected) << "dims " << dims << " sigma " << sigma;
    }
}

TEST(StateRepresentation, SpatialIndexMatchesBruteForce) {
    for (bool circular : {false, true}) {
        for (std::uint32_t resolution : {3u, 8u, 14u, 25u}) {
            AgentDescriptor d;
            d.addContinuousSensor(circular).addContinuousSensor().addContinuousSensor(circular);
            d.resolution = resolution;
            d.adaptation &= ~verve::Adaptation::PairsBeside;  // one lattice: the brute force knows one
            StateRepresentation rep(d);
            verve::core::Rng rng(resolution);
            std::vector<ActiveFeature> phi;
            float p[3];
            for (int i = 0; i < 3000; ++i) {
                for (float& x : p) x = rng.uniform() * 2 - 1;
                rep.activate(nullptr, p, true, phi);
            }
            expectIndexMatchesBruteForce(rep, 3, {circular, false, circular}, 2.0f / static_cast<float>(resolution), rng, 300);
        }
    }
}

// A small lattice (at most 1,024 RBFs in all: one sensor up to resolution 1,024, two up to 32) is
// one cell read through its block boxes; two sensors at resolution 40 keep the grid. One lattice
// each (the fine one cleared): the brute force knows one width.
TEST(StateRepresentation, SmallLatticesInOneCellMatchBruteForce) {
    for (bool circular : {false, true}) {
        for (auto [dims, resolution] : {std::pair{1u, 20u}, {1u, 1024u}, {2u, 20u}, {2u, 32u}, {2u, 40u}}) {
            AgentDescriptor d;
            for (std::uint32_t k = 0; k < dims; ++k) d.addContinuousSensor(circular && k == 0);
            d.resolution = resolution;
            d.adaptation &= ~verve::Adaptation::FineLattice;
            StateRepresentation rep(d);
            verve::core::Rng rng(resolution + dims);
            std::vector<ActiveFeature> phi;
            float p[2];
            for (int i = 0; i < 3000; ++i) {
                for (std::uint32_t k = 0; k < dims; ++k) p[k] = rng.uniform() * 2 - 1;
                rep.activate(nullptr, p, true, phi);
            }
            expectIndexMatchesBruteForce(rep, dims, {circular, false}, 2.0f / static_cast<float>(resolution), rng, 300);
        }
    }
}

// Full 4-D lattices: cells stored in Morton order, read block by block through their boxes.
TEST(StateRepresentation, SpatialIndexMatchesBruteForceOnFullLattices) {
    for (bool circular : {false, true}) {
        for (std::uint32_t resolution : {6u, 9u, 13u}) {
            AgentDescriptor d;
            for (int k = 0; k < 4; ++k) d.addContinuousSensor(circular && k % 2 == 0);
            d.resolution = resolution;
            d.allocation = verve::RbfAllocation::Full;
            d.adaptation &= ~verve::Adaptation::PairsBeside;  // one lattice: the brute force knows one
            StateRepresentation rep(d);
            verve::core::Rng rng(resolution);
            expectIndexMatchesBruteForce(rep, 4, {circular, false, circular, false}, 2.0f / static_cast<float>(resolution),
                                         rng, 100);
        }
    }
}

// A dynamic agent's RBFs lie along the paths it took: on the cart-pole shape (4 sensors,
// resolution 8, one cell of ~700 RBFs) nearly every block box passes, so lookups stop testing
// the boxes and read the cell whole for a while. Both ways must find exactly what a scan of
// every RBF finds.
TEST(StateRepresentation, CellsReadWholeWhenBlockBoxesSkipLittle) {
    AgentDescriptor d;
    for (int k = 0; k < 4; ++k) d.addContinuousSensor();
    d.resolution = 8;
    d.adaptation &= ~verve::Adaptation::PairsBeside;  // one lattice, as the crowd's one-lattice agents
    StateRepresentation rep(d);
    std::vector<ActiveFeature> phi;
    auto pathPoint = [](int t, float* p) {
        for (int k = 0; k < 4; ++k) {
            const float x = 0.011f * static_cast<float>(t);
            p[k] = 0.6f * std::sin(x * (1.0f + 0.37f * k) + k) + 0.3f * std::sin(x * (3.1f + 0.53f * k));
        }
    };
    float p[4];
    int t = 0;
    for (; rep.featureCount() < 600; ++t) {
        pathPoint(t, p);
        rep.activate(nullptr, p, true, phi);
    }
    std::vector<std::uint64_t> keys;
    std::vector<float> centres;
    rep.features(keys, centres);
    const float sigma = 2.0f / 8.0f;
    int whole = 0, boxed = 0;
    for (int q = 0; q < 400; ++q) {
        pathPoint(7 * q + 3, p);  // on the path, where lookups happen
        (rep.readsCellsWhole() ? whole : boxed) += 1;
        rep.find(nullptr, p, phi);
        std::vector<ActiveFeature> expected;
        for (std::uint32_t f = 0; f < rep.featureCount(); ++f) {
            float d2 = 0;
            for (int k = 0; k < 4; ++k) d2 += (p[k] - centres[f * 4 + k]) * (p[k] - centres[f * 4 + k]);
            if (d2 < 16 * sigma * sigma) expected.emplace_back(f, std::exp(-d2 / (2 * sigma * sigma)));
        }
        ASSERT_EQ(phi.size(), expected.size()) << "query " << q;
        for (std::size_t i = 0; i < phi.size(); ++i) {  // one cell, in allocation order
            EXPECT_EQ(phi[i].index, expected[i].index);
            EXPECT_NEAR(phi[i].activation, expected[i].activation, 1e-5f);
        }
    }
    EXPECT_GT(whole, 300);  // mostly whole: nearly every box passes on this shape
    EXPECT_GT(boxed, 0);    // and the boxes are measured again now and then
}

// In a dense lattice most blocks lie beyond the cutoff: the boxes keep being tested.
TEST(StateRepresentation, DenseLatticesKeepTestingBlockBoxes) {
    AgentDescriptor d;
    for (int k = 0; k < 4; ++k) d.addContinuousSensor();
    d.resolution = 13;
    d.allocation = verve::RbfAllocation::Full;
    StateRepresentation rep(d);
    verve::core::Rng rng(5);
    std::vector<ActiveFeature> phi;
    float p[4];
    for (int q = 0; q < 200; ++q) {
        for (float& x : p) x = rng.uniform() * 2 - 1;
        rep.find(nullptr, p, phi);
        EXPECT_FALSE(rep.readsCellsWhole()) << "query " << q;
    }
}
