// Descriptors and saves an attacker or a careless host could hand the C ABI: every derived size
// is bounded (validation by total size, not per field), and no loaded value can make an update
// loop for ever or read out of bounds.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "hardening_support.hpp"

namespace verve::hardening {
namespace {

verve_agent_desc planningDesc() {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_discrete_sensors = 1;
    d.discrete_sensor_values[0] = 4;
    d.num_actions = 3;
    d.planning = 1;
    return d;
}

void expectCreateRefused(const verve_agent_desc& d, const char* named) {
    verve_agent* out = nullptr;
    EXPECT_EQ(verve_agent_create(&d, &out), VERVE_ERROR_INVALID_ARGUMENT) << named;
    EXPECT_EQ(out, nullptr);
    EXPECT_NE(lastError().find(named), std::string::npos) << lastError();
    verve_agent_destroy(out);
}

TEST(TotalSize, PlanningModelSizesThatOverflowAreRefused) {
    verve_agent_desc d = planningDesc();
    d.discrete_sensor_values[0] = 4294967295u;  // once wrapped the model's uint32 block size
    expectCreateRefused(d, "discrete_sensor_values");

    d = planningDesc();
    d.discrete_sensor_values[0] = 1u << 20;
    d.num_actions = 4096;
    expectCreateRefused(d, "discrete_sensor_values");

    d = planningDesc();
    d.discrete_sensor_values[0] = 60000;  // outputs per action fit, but not 100 of them per RBF
    d.num_actions = 100;
    expectCreateRefused(d, "num_actions");
}

TEST(TotalSize, PerFieldLimitsNameTheCField) {
    verve_agent_desc d = planningDesc();
    d.planning = 0;
    d.discrete_sensor_values[0] = 4294967295u;  // readings are int32: no value above 2^31 - 1
    expectCreateRefused(d, "discrete_sensor_values[0]");
    d = planningDesc();
    d.num_actions = 4097;
    expectCreateRefused(d, "num_actions");
    d = planningDesc();
    d.num_discrete_sensors = 3;
    d.discrete_sensor_values[1] = 1u << 30;
    d.discrete_sensor_values[2] = 1u << 30;
    d.planning = 0;
    expectCreateRefused(d, "discrete_sensor_values");  // 2^62 combinations
    d.discrete_sensor_values[0] = 1u << 19;
    d.discrete_sensor_values[1] = 1u << 19;
    d.discrete_sensor_values[2] = 1u << 26;
    expectCreateRefused(d, "discrete_sensor_values");  // 2^64, which wraps to 0 (found by fuzz_crowd)
    d = planningDesc();
    d.planning = 0;
    d.num_continuous_sensors = 4;
    d.resolution = 100;
    d.rbf_allocation = VERVE_RBF_FULL;  // 4 * 100^4 RBFs up front
    expectCreateRefused(d, "rbf_allocation");
}

TEST(TotalSize, LargestAcceptedPlanningAgentWorks) {
    verve_agent_desc d = planningDesc();
    d.discrete_sensor_values[0] = 65531;  // + 5 scalar outputs = the documented 65536
    d.num_actions = 2;
    verve_agent* agent = nullptr;
    ASSERT_EQ(verve_agent_create(&d, &agent), VERVE_OK) << lastError();
    for (int32_t i = 0; i < 5; ++i) {
        const int32_t v = i * 1000;
        uint32_t action = 0;
        ASSERT_EQ(verve_agent_update(agent, 0.5f, &v, 1, nullptr, 0, 0.1f, &action), VERVE_OK) << lastError();
    }
    verve_agent_destroy(agent);
}

TEST(TotalSize, LoadedSavesObeyTheSameLimits) {
    verve_agent* agent = createOrFail(planningDesc());
    const std::string xml = saveToString(agent);
    verve_agent_destroy(agent);
    for (const char* values : {"4294967295", "1048576", "500000000"}) {
        const std::string bad = replaceAttribute(xml, "discrete_sensor", "values", values);
        verve_agent* out = nullptr;
        EXPECT_EQ(verve_agent_load_memory(bad.data(), bad.size(), &out), VERVE_ERROR_FORMAT) << values;
        EXPECT_EQ(out, nullptr);
        EXPECT_NE(lastError().find("discrete_sensor_values"), std::string::npos) << lastError();
    }
}

// A saved model weight of 3.4e7 or more once made the circular wrap subtract 2 for ever.
TEST(LoadedValues, HugeModelWeightsOnACircularSensorDoNotHang) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_continuous_sensors = 1;
    d.continuous_sensor_circular[0] = 1;
    d.num_actions = 2;
    d.planning = 1;
    verve_agent* agent = createOrFail(d);
    for (int i = 0; i < 20; ++i) {
        const float c = static_cast<float>(i % 10) / 5.0f - 1.0f;
        uint32_t action = 0;
        ASSERT_EQ(verve_agent_update(agent, 0.0f, nullptr, 0, &c, 1, 0.1f, &action), VERVE_OK);
    }
    const std::string xml = saveToString(agent);
    verve_agent_destroy(agent);
    // Beyond +-1e20 (AgentSnapshot::kWeightLimit) a weight is refused as corrupt: from 1e28 on, one
    // model update could overflow a weight to inf.
    for (const char* weight : {"1e30", "3.4e38", "-2e20"}) {
        const std::string bad = replaceList(xml, "weights", weight);
        verve_agent* loaded = nullptr;
        EXPECT_EQ(verve_agent_load_memory(bad.data(), bad.size(), &loaded), VERVE_ERROR_FORMAT) << weight;
        EXPECT_EQ(loaded, nullptr);
    }
    for (const char* weight : {"3.4e7", "-3.4e7", "1e20", "-1e20"}) {
        const std::string bad = replaceList(xml, "weights", weight);
        verve_agent* loaded = nullptr;
        ASSERT_EQ(verve_agent_load_memory(bad.data(), bad.size(), &loaded), VERVE_OK) << weight << ": " << lastError();
        for (int i = 0; i < 20; ++i) {
            const float c = 0.3f;
            uint32_t action = 99;
            ASSERT_EQ(verve_agent_update(loaded, 1.0f, nullptr, 0, &c, 1, 0.1f, &action), VERVE_OK) << lastError();
            ASSERT_LT(action, 2u);
        }
        verve_agent_destroy(loaded);
    }
}

// The base arrays are as long as the host says: the counts are checked before they are read.
TEST(SampleValues, CountsAreCheckedBeforeTheBaseArraysAreRead) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_discrete_sensors = 1;
    d.discrete_sensor_values[0] = 3;
    d.num_continuous_sensors = 1;
    verve_agent* agent = createOrFail(d);
    const int32_t disc = 0;
    const float cont = 0.0f;
    verve_value_axis axis{VERVE_SENSOR_CONTINUOUS, 0, 4};
    float out[4] = {};
    EXPECT_EQ(verve_agent_sample_values(agent, &axis, 1, &disc, 1u << 30, &cont, 1, out, 4), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("n_discrete"), std::string::npos) << lastError();
    EXPECT_EQ(verve_agent_sample_values(agent, &axis, 1, &disc, 1, &cont, 1u << 30, out, 4), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("n_continuous"), std::string::npos) << lastError();
    EXPECT_EQ(verve_agent_sample_values(agent, &axis, 1, &disc, 2, &cont, 1, out, 4), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_agent_sample_values(agent, &axis, 1, &disc, 1, &cont, 1, out, 4), VERVE_OK) << lastError();
    verve_agent_destroy(agent);
}

}  // namespace
}  // namespace verve::hardening
