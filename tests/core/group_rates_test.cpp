// Which sensor groups matter (core/group_rates.hpp): which agents learn a rate per group, how the
// rates share the step, and that the group whose sensor predicts the reward gains (saves:
// tests/io/round_trip_test.cpp; a batch's bodies over thread counts: tests/capi/crowd_test.cpp).
#include "core/group_rates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "continuous_sensors.hpp"
#include "core/state_representation.hpp"
#include "verve/agent.hpp"

using namespace verve;
using verve::coretest::continuousSensors;
using verve::coretest::withoutAdaptation;
using verve::core::GroupRates;
using verve::core::StateRepresentation;

TEST(GroupRates, OnlyAgentsOfTwoOrMoreSensorGroupsWithTheBitLearnThem) {
    for (std::size_t n : {0u, 1u, 2u, 3u, 4u}) EXPECT_FALSE(GroupRates::appliesTo(continuousSensors(n))) << n;
    for (std::size_t n : {5u, 12u, 32u}) {
        EXPECT_TRUE(GroupRates::appliesTo(continuousSensors(n))) << n;
        EXPECT_FALSE(GroupRates::appliesTo(withoutAdaptation(continuousSensors(n), Adaptation::GroupRates))) << n;
    }
    AgentDescriptor joint = continuousSensors(6);
    joint.grouping = SensorGrouping::Joint;
    EXPECT_FALSE(GroupRates::appliesTo(joint));
    AgentDescriptor custom = continuousSensors(3);
    custom.grouping = SensorGrouping::Custom;
    custom.sensorGroups = {0b101, 0b010};
    EXPECT_TRUE(GroupRates::appliesTo(custom));
    custom.sensorGroups = {0b111};
    EXPECT_FALSE(GroupRates::appliesTo(custom));
    const StateRepresentation rep(continuousSensors(2));
    EXPECT_FALSE(GroupRates(continuousSensors(2), rep).active());
    EXPECT_EQ(GroupRates(continuousSensors(2), rep).traceLimit(rep), 1.0f);
}

// What one lattice gains the others give: the scales' mean weighted by the lattices' activation
// sums stays 1, so the whole step is what it was; a lattice pushed the same way keeps rising.
TEST(GroupRates, ScalesShareTheStepAndFollowTheGradient) {
    const AgentDescriptor d = continuousSensors(6);  // 6 singles and 5 pairs
    const StateRepresentation rep(d);
    GroupRates rates(d, rep);
    ASSERT_TRUE(rates.active());
    ASSERT_EQ(rates.lattices(), 11u);
    std::vector<float> g(rates.lattices(), -1.0f);
    g[0] = 1.0f;
    for (int step = 0; step < 200; ++step) rates.apply(rep, g.data());
    double weighted = 0.0, total = 0.0;
    for (std::size_t k = 0; k < rates.lattices(); ++k) {
        weighted += rates.scaleOf(k) * rep.latticeSum(k);
        total += rep.latticeSum(k);
        if (k > 0) EXPECT_GT(rates.scaleOf(0), 10.0f * rates.scaleOf(k)) << k;
    }
    EXPECT_NEAR(weighted / total, 1.0, 1e-5);
    EXPECT_LE(rates.scaleOf(0), rates.traceLimit(rep));
    EXPECT_NEAR(rates.logRates()[0], 2.0f, 1e-3f);  // 200 steps of the largest change, 0.01 each
    // Bad gradients change nothing; a rate never leaves +-6.
    const std::vector<float> before = rates.logRates();
    std::vector<float> bad(rates.lattices(), std::nanf(""));
    rates.apply(rep, bad.data());
    EXPECT_EQ(rates.logRates(), before);
    for (int step = 0; step < 2000; ++step) rates.apply(rep, g.data());
    EXPECT_FLOAT_EQ(rates.logRates()[0], GroupRates::kLogLimit);
    EXPECT_FLOAT_EQ(rates.logRates()[1], -GroupRates::kLogLimit);
}

// Six sensors, the reward decided by sensor 0 alone (+1 on one side, -1 on the other) and the
// others noise: the rate of sensor 0's own lattice rises above every other single sensor's.
TEST(GroupRates, TheGroupWhoseSensorPredictsTheRewardGainsTheMost) {
    AgentDescriptor d = continuousSensors(6);
    d.numActions = 2;
    Agent agent(d);
    std::uint64_t state = 7;
    const auto noise = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<float>((state >> 40) & 0xFFFF) / 32768.0f - 1.0f;
    };
    float x[6] = {};
    float reward = 0.0f;
    for (int step = 0; step < 4000; ++step) {
        x[0] = std::sin(0.05f * static_cast<float>(step));  // drifts slowly, as a position does
        for (int i = 1; i < 6; ++i) x[i] = noise();
        agent.update(reward, ObservationView{nullptr, 0, x, 6}, 0.1f);
        reward = x[0] > 0.0f ? 1.0f : -1.0f;
    }
    const AgentSnapshot snap = agent.snapshot();
    ASSERT_EQ(snap.groupLogRates.size(), 11u);
    for (std::size_t k = 1; k < 6; ++k) EXPECT_GT(snap.groupLogRates[0], snap.groupLogRates[k]) << k;
}
