// Sensor groups: which lattices Auto makes, how a grouped representation finds and adds RBFs, and
// the descriptor's checks of custom groups.
#include "core/sensor_groups.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "continuous_sensors.hpp"
#include "core/state_representation.hpp"
#include "validation_error.hpp"
#include "verve/error.hpp"

using namespace verve;
using verve::coretest::continuousSensors;
using verve::coretest::withoutAdaptation;
using verve::coretest::validationError;
using verve::core::ActiveFeature;
using verve::core::StateRepresentation;

TEST(SensorGroups, AutoKeepsOneLatticeUpToFourSensorsThenSinglesAndNeighbouringPairs) {
    EXPECT_EQ(core::sensorGroups(continuousSensors(0)), std::vector<std::uint64_t>{0});
    EXPECT_EQ(core::sensorGroups(continuousSensors(4)), std::vector<std::uint64_t>{0b1111});
    EXPECT_EQ(core::sensorGroups(continuousSensors(5)),
              (std::vector<std::uint64_t>{0b1, 0b10, 0b100, 0b1000, 0b10000, 0b11, 0b110, 0b1100, 0b11000}));
    AgentDescriptor joint = continuousSensors(16);
    joint.grouping = SensorGrouping::Joint;
    EXPECT_EQ(core::sensorGroups(joint), std::vector<std::uint64_t>{0xFFFF});
    EXPECT_EQ(core::sensorGroups(continuousSensors(16)).size(), 31u);
}

TEST(SensorGroups, EachGroupGrowsItsOwnRbfAndTheFeaturesAreSummed) {
    AgentDescriptor d = continuousSensors(6);
    d.resolution = 10;
    StateRepresentation rep(d);
    ASSERT_EQ(rep.groupCount(), 11u);
    EXPECT_NEAR(rep.activationSum(), 6 * 2.5f + 5 * 6.25f, 1e-3f);
    std::vector<ActiveFeature> phi;
    const std::vector<float> a{0.1f, -0.2f, 0.3f, 0.0f, 0.5f, -0.9f};
    EXPECT_EQ(rep.activate(nullptr, a.data(), true, phi), 11u);  // one RBF per group
    EXPECT_EQ(rep.featureCount(), 11u);
    EXPECT_EQ(rep.activate(nullptr, a.data(), true, phi), 0u);
    EXPECT_EQ(phi.size(), 11u);
    for (const auto& f : phi) EXPECT_FLOAT_EQ(f.activation, 1.0f);
    // Only the last sensor moves far: its single and its pair need new RBFs, nothing else.
    std::vector<float> b = a;
    b[5] = 0.9f;
    EXPECT_EQ(rep.activate(nullptr, b.data(), true, phi), 2u);
    EXPECT_EQ(rep.featureCount(), 13u);
    // Saved keys name the group; the centre holds the group's sensors and 0 elsewhere.
    std::vector<std::uint64_t> keys;
    std::vector<float> centres;
    rep.features(keys, centres);
    EXPECT_EQ(keys[0], 0u);
    EXPECT_EQ(keys[6], 6u);  // the first pair (sensors 0 and 1)
    EXPECT_FLOAT_EQ(centres[6 * 6 + 0], 0.1f);
    EXPECT_FLOAT_EQ(centres[6 * 6 + 1], -0.2f);
    EXPECT_FLOAT_EQ(centres[6 * 6 + 2], 0.0f);
    // Restored in order, the same representation.
    StateRepresentation copy(d);
    for (std::size_t i = 0; i < keys.size(); ++i) copy.addFeature(keys[i], centres.data() + i * 6);
    std::vector<ActiveFeature> again;
    copy.find(nullptr, b.data(), again);
    rep.find(nullptr, b.data(), phi);
    ASSERT_EQ(again.size(), phi.size());
    for (std::size_t i = 0; i < phi.size(); ++i) {
        EXPECT_EQ(again[i].index, phi[i].index);
        EXPECT_FLOAT_EQ(again[i].activation, phi[i].activation);
    }
}

TEST(SensorGroups, FullAllocationMakesEveryGroupsLattice) {
    AgentDescriptor d = continuousSensors(3);
    d.addDiscreteSensor(2);
    d.resolution = 4;
    d.allocation = RbfAllocation::Full;
    d.grouping = SensorGrouping::Custom;
    d.sensorGroups = {0b011, 0b100};
    StateRepresentation rep(d);
    EXPECT_EQ(rep.featureCount(), 2u * (16u + 4u));
    EXPECT_EQ(rep.keyCount(), 4u);  // 2 groups x 2 discrete values
}

TEST(SensorGroups, CustomGroupsAreChecked) {
    AgentDescriptor d = continuousSensors(3);
    d.sensorGroups = {0b111};
    EXPECT_NE(validationError(d).find("sensor_groups is only read with Custom sensor_grouping"), std::string::npos);
    d.grouping = SensorGrouping::Custom;
    EXPECT_EQ(validationError(d), "");
    d.sensorGroups = {0b011};
    EXPECT_NE(validationError(d).find("continuous sensor 2 is in none of sensor_groups"), std::string::npos);
    d.sensorGroups = {0b111, 0};
    EXPECT_NE(validationError(d).find("sensor_groups[1] is empty"), std::string::npos);
    d.sensorGroups = {0b1111};
    EXPECT_NE(validationError(d).find("sensor_groups[0] names a continuous sensor the agent does not have (bit 3)"),
              std::string::npos);
    d.sensorGroups.assign(65, 0b111);
    EXPECT_NE(validationError(d).find("at most 64"), std::string::npos);
    d.sensorGroups.clear();
    EXPECT_NE(validationError(d).find("needs at least one group"), std::string::npos);
    d.grouping = static_cast<SensorGrouping>(7);
    EXPECT_NE(validationError(d).find("sensor_grouping must be Auto, Joint or Custom"), std::string::npos);
    // A full lattice counts every group's RBFs.
    AgentDescriptor full = continuousSensors(8);
    full.resolution = 100;
    full.allocation = RbfAllocation::Full;
    EXPECT_EQ(validationError(full), "");  // 8 x 100 + 7 x 10,000 RBFs
    full.grouping = SensorGrouping::Joint;
    EXPECT_NE(validationError(full).find("per group"), std::string::npos);
}

// An agent may have 64 sensors of each kind (a group is a 64-bit mask); one lattice spans at most
// 16 (its lookup's inline arrays), and Auto's 2n - 1 lattices fit 64 groups up to 32 sensors.
TEST(SensorGroups, UpTo64SensorsWithNoLatticeOverMoreThan16) {
    EXPECT_EQ(validationError(continuousSensors(32)), "");
    EXPECT_EQ(core::sensorGroups(continuousSensors(32)).size(), 63u);
    EXPECT_NE(validationError(continuousSensors(33)).find("33 continuous sensors make 65 AUTO sensor_groups"), std::string::npos)
        << validationError(continuousSensors(33));
    AgentDescriptor joint = continuousSensors(17);
    joint.grouping = SensorGrouping::Joint;
    EXPECT_NE(validationError(joint).find("JOINT sensor_grouping puts all 17 continuous sensors in one lattice, which spans "
                                          "at most 16; use AUTO or CUSTOM sensor_grouping"),
              std::string::npos)
        << validationError(joint);
    joint.continuousSensors.resize(16);
    EXPECT_EQ(validationError(joint), "");
    AgentDescriptor custom = continuousSensors(64);
    custom.grouping = SensorGrouping::Custom;
    custom.sensorGroups = {0xFFFF, 0xFFFFull << 16, 0xFFFFull << 32, 0xFFFFull << 48};
    EXPECT_EQ(validationError(custom), "");
    StateRepresentation rep(custom);
    EXPECT_EQ(rep.groupCount(), 4u);
    std::vector<float> x(64, 0.3f);
    std::vector<ActiveFeature> phi;
    EXPECT_EQ(rep.activate(nullptr, x.data(), true, phi), 4u);
    custom.sensorGroups[1] |= 1ull << 32;  // 17 sensors
    EXPECT_NE(validationError(custom).find("sensor_groups[1] spans 17 continuous sensors, one lattice at most 16; split it"),
              std::string::npos)
        << validationError(custom);
    custom = continuousSensors(65);
    EXPECT_NE(validationError(custom).find("num_continuous_sensors is 65, at most 64"), std::string::npos);
    AgentDescriptor discrete;
    for (int i = 0; i < 64; ++i) discrete.addDiscreteSensor(i < 40 ? 2 : 1);
    EXPECT_EQ(validationError(discrete), "");
    discrete.addDiscreteSensor(1);
    EXPECT_NE(validationError(discrete).find("num_discrete_sensors is 65, at most 64"), std::string::npos);
    // C++ names in C++ messages.
    joint.continuousSensors.resize(20);
    try {
        joint.validate();
        ADD_FAILURE() << "Joint over 20 sensors accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("Joint grouping puts all 20"), std::string::npos) << e.what();
    }
}
