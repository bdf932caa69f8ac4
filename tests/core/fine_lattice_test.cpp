// The fine lattice beside a small one (core/fine_lattice.hpp): which agents get it, how it adds
// RBFs and counts in the learning rates (saves: tests/io/fine_lattice_save_test.cpp).
#include "core/fine_lattice.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "core/sensor_groups.hpp"
#include "continuous_sensors.hpp"
#include "core/state_representation.hpp"

using namespace verve;
using verve::coretest::continuousSensors;
using verve::coretest::withoutAdaptation;
using verve::core::ActiveFeature;
using verve::core::StateRepresentation;

TEST(FineLattice, OneOrTwoSensorsGetALatticeAtTwiceTheResolution) {
    for (std::size_t n : {1u, 2u}) {
        const auto specs = core::lattices(continuousSensors(n));
        ASSERT_EQ(specs.size(), 2u) << n;
        EXPECT_EQ(specs[0].resolution, 10u);
        EXPECT_FLOAT_EQ(specs[0].share, 1.0f);
        EXPECT_EQ(specs[1].sensors, specs[0].sensors);
        EXPECT_EQ(specs[1].resolution, 20u);
        EXPECT_FLOAT_EQ(specs[1].share, core::kFineActivationShare);
    }
}

TEST(FineLattice, NoneForMoreSensorsGroupsNoSensorsOrWhenNotAsked) {
    for (std::size_t n : {3u, 4u}) {  // pairs beside their lattice instead (core/pairs_beside.hpp)
        for (const auto& spec : core::lattices(continuousSensors(n))) EXPECT_EQ(spec.resolution, 10u) << n;
    }
    EXPECT_EQ(core::lattices(continuousSensors(6)).size(), core::sensorGroups(continuousSensors(6)).size());  // groups: none
    AgentDescriptor discrete;
    discrete.addDiscreteSensor(3);
    EXPECT_EQ(core::lattices(discrete).size(), 1u);
    discrete.grouping = SensorGrouping::Custom;  // no continuous sensors, no groups (found by fuzz_calls)
    EXPECT_TRUE(core::lattices(discrete).empty());
    EXPECT_EQ(core::lattices(withoutAdaptation(continuousSensors(2), Adaptation::FineLattice)).size(), 1u);
    AgentDescriptor custom = continuousSensors(2);
    custom.grouping = SensorGrouping::Custom;
    custom.sensorGroups = {0b01, 0b10};
    EXPECT_EQ(core::lattices(custom).size(), 2u);  // two lattices already: no fine ones
    AgentDescriptor fine = continuousSensors(1);
    fine.resolution = DescriptorLimits::kMaxResolution;  // twice that is past the limit
    EXPECT_EQ(core::lattices(fine).size(), 1u);
    fine.resolution = DescriptorLimits::kMaxResolution / 2;
    EXPECT_EQ(core::lattices(fine).back().resolution, DescriptorLimits::kMaxResolution);
}

TEST(FineLattice, AddsAnRbfOfItsOwnAndCountsHalfInTheLearningRates) {
    AgentDescriptor d = continuousSensors(1);
    StateRepresentation rep(d);
    StateRepresentation alone(withoutAdaptation(d, Adaptation::FineLattice));
    EXPECT_FLOAT_EQ(rep.activationSum(), alone.activationSum() * (1.0f + core::kFineActivationShare));
    std::vector<ActiveFeature> phi;
    const float x = 0.3f;
    EXPECT_EQ(rep.activate(nullptr, &x, true, phi), 2u);  // one in each lattice
    // 0.15 is within one width (0.2) of the coarse RBF but not of the fine one (0.1).
    const float near = 0.15f;
    EXPECT_EQ(rep.activate(nullptr, &near, true, phi), 1u);
    ASSERT_EQ(phi.size(), 3u);
    std::vector<std::uint64_t> keys;
    std::vector<float> centres;
    rep.features(keys, centres);
    EXPECT_EQ(keys, (std::vector<std::uint64_t>{0, 1, 1}));  // lattice 0, then the fine lattice 1
    EXPECT_FLOAT_EQ(centres[2], 0.15f);
}
