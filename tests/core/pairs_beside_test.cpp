// Neighbouring pairs beside a lattice of 3-4 sensors (core/pairs_beside.hpp): which agents get
// them, and how they count in the learning rates (saves: tests/io/fine_lattice_save_test.cpp).
#include "core/pairs_beside.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "continuous_sensors.hpp"
#include "core/state_representation.hpp"

using namespace verve;
using verve::coretest::continuousSensors;
using verve::coretest::withoutAdaptation;
using verve::core::ActiveFeature;
using verve::core::StateRepresentation;

TEST(PairsBeside, ThreeOrFourSensorsGetALatticePerNeighbouringPair) {
    const std::vector<std::uint64_t> three = {0b111, 0b011, 0b110};
    const std::vector<std::uint64_t> four = {0b1111, 0b0011, 0b0110, 0b1100};
    for (const auto& expected : {three, four}) {
        const auto specs = core::lattices(continuousSensors(expected.size()));
        ASSERT_EQ(specs.size(), expected.size());
        for (std::size_t i = 0; i < specs.size(); ++i) {
            EXPECT_EQ(specs[i].sensors, expected[i]) << i;
            EXPECT_EQ(specs[i].resolution, 10u);
            EXPECT_FLOAT_EQ(specs[i].share, i == 0 ? 1.0f : core::kPairsBesideActivationShare);
        }
    }
}

TEST(PairsBeside, NoneForFewerOrMoreSensorsOtherGroupingsOrWhenNotAsked) {
    for (std::size_t n : {0u, 1u, 2u, 5u, 12u}) {
        EXPECT_EQ(core::lattices(continuousSensors(n)).size(), core::lattices(withoutAdaptation(continuousSensors(n), Adaptation::PairsBeside)).size()) << n;
    }
    EXPECT_EQ(core::lattices(withoutAdaptation(continuousSensors(4), Adaptation::PairsBeside)).size(), 1u);
    AgentDescriptor joint = continuousSensors(4);
    joint.grouping = SensorGrouping::Joint;
    EXPECT_EQ(core::lattices(joint).size(), 1u);
    AgentDescriptor custom = continuousSensors(3);
    custom.grouping = SensorGrouping::Custom;
    custom.sensorGroups = {0b111};
    EXPECT_EQ(core::lattices(custom).size(), 1u);  // the user's layout, as given
}

TEST(PairsBeside, EachPairAddsItsOwnRbfsAndCountsItsShareInTheLearningRates) {
    const AgentDescriptor d = continuousSensors(3);
    StateRepresentation rep(d);
    StateRepresentation alone(withoutAdaptation(d, Adaptation::PairsBeside));
    AgentDescriptor custom = d;  // the same pairs as Custom groups count whole
    custom.grouping = SensorGrouping::Custom;
    custom.sensorGroups = {0b011, 0b110};
    StateRepresentation pairs(custom);
    EXPECT_FLOAT_EQ(rep.activationSum(), alone.activationSum() + core::kPairsBesideActivationShare * pairs.activationSum());
    std::vector<ActiveFeature> phi;
    const float x[3] = {0.3f, -0.2f, 0.7f};
    EXPECT_EQ(rep.activate(nullptr, x, true, phi), 3u);  // one new RBF in each lattice
    EXPECT_EQ(rep.featureCount(), 3u);
}
