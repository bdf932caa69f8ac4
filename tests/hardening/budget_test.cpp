// The RBF budget (max_rbfs): an agent fed noise stops growing at its budget and keeps working,
// its stats say so, and a loaded save obeys the budget too. Struct versions stay compatible.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>

#include "hardening_support.hpp"

namespace verve::hardening {
namespace {

verve_agent_desc noiseDesc(uint64_t maxRbfs) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_continuous_sensors = 3;
    d.resolution = 20;
    d.num_actions = 3;
    d.max_rbfs = maxRbfs;
    return d;
}

verve_agent_stats statsOf(const verve_agent* agent) {
    verve_agent_stats s{};
    s.struct_size = sizeof s;
    EXPECT_EQ(verve_agent_get_stats(agent, &s), VERVE_OK) << lastError();
    return s;
}

void feedNoise(verve_agent* agent, int steps) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < steps; ++i) {
        const float c[3] = {u(rng), u(rng), u(rng)};
        uint32_t action = 99;
        ASSERT_EQ(verve_agent_update(agent, u(rng), nullptr, 0, c, 3, 0.1f, &action), VERVE_OK) << lastError();
        ASSERT_LT(action, 3u);
    }
}

TEST(RbfBudget, DefaultIsAMillion) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    EXPECT_EQ(d.max_rbfs, 1000000u);
    EXPECT_EQ(d.struct_size, VERVE_AGENT_DESC_SIZE_V8);
}

TEST(RbfBudget, NoiseStopsAtTheBudgetAndTheAgentKeepsWorking) {
    verve_agent* agent = createOrFail(noiseDesc(200));
    feedNoise(agent, 3000);
    const verve_agent_stats s = statsOf(agent);
    EXPECT_EQ(s.rbf_count, 200u);
    EXPECT_GT(s.rbf_budget_hits, 0u);
    EXPECT_EQ(s.steps, 3000u);
    // Still learning from the RBFs it has: values move.
    float before = 0.0f, after = 0.0f;
    const float c[3] = {0.1f, 0.2f, 0.3f};
    uint32_t action = 0;
    ASSERT_EQ(verve_agent_update(agent, 0.0f, nullptr, 0, c, 3, 0.1f, &action), VERVE_OK);
    ASSERT_EQ(verve_agent_get_value(agent, &before), VERVE_OK);
    for (int i = 0; i < 50; ++i) ASSERT_EQ(verve_agent_update(agent, 1.0f, nullptr, 0, c, 3, 0.1f, &action), VERVE_OK);
    ASSERT_EQ(verve_agent_get_value(agent, &after), VERVE_OK);
    EXPECT_GT(after, before);
    EXPECT_EQ(statsOf(agent).rbf_count, 200u);
    verve_agent_destroy(agent);
}

TEST(RbfBudget, ZeroMeansUnlimited) {
    verve_agent* agent = createOrFail(noiseDesc(0));
    feedNoise(agent, 3000);
    const verve_agent_stats s = statsOf(agent);
    EXPECT_GT(s.rbf_count, 200u);
    EXPECT_EQ(s.rbf_budget_hits, 0u);
    verve_agent_destroy(agent);
}

TEST(RbfBudget, ALoadedSaveObeysItsBudget) {
    verve_agent* agent = createOrFail(noiseDesc(200));
    feedNoise(agent, 500);
    const std::string xml = saveToString(agent);
    verve_agent_destroy(agent);
    verve_agent* loaded = nullptr;
    ASSERT_EQ(verve_agent_load_memory(xml.data(), xml.size(), &loaded), VERVE_OK) << lastError();
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    ASSERT_EQ(verve_agent_get_desc(loaded, &d), VERVE_OK);
    EXPECT_EQ(d.max_rbfs, 200u);
    verve_agent_destroy(loaded);

    const std::string shrunk = replaceAttribute(xml, "descriptor", "max_rbfs", "10");
    loaded = nullptr;
    EXPECT_EQ(verve_agent_load_memory(shrunk.data(), shrunk.size(), &loaded), VERVE_ERROR_FORMAT);
    EXPECT_EQ(loaded, nullptr);
    EXPECT_NE(lastError().find("max_rbfs"), std::string::npos) << lastError();
}

TEST(RbfBudget, FullLatticeBeyondTheBudgetIsRefused) {
    verve_agent_desc d = noiseDesc(1000);
    d.rbf_allocation = VERVE_RBF_FULL;  // 20^3 = 8000 RBFs up front
    verve_agent* out = nullptr;
    EXPECT_EQ(verve_agent_create(&d, &out), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("max_rbfs"), std::string::npos) << lastError();
    d.max_rbfs = 0x100000000ull;  // beyond 32-bit feature indices
    d.rbf_allocation = VERVE_RBF_DYNAMIC;
    EXPECT_EQ(verve_agent_create(&d, &out), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("max_rbfs"), std::string::npos) << lastError();
}

// A host built against the V2 header passes the V2 size: the budget takes its default.
TEST(RbfBudget, OlderStructSizesKeepWorking) {
    unsigned char memory[sizeof(verve_agent_desc)];
    std::memset(memory, 0xAB, sizeof memory);
    auto* d = reinterpret_cast<verve_agent_desc*>(memory);
    ASSERT_EQ(verve_agent_desc_init(d, VERVE_AGENT_DESC_SIZE_V2), VERVE_OK);
    for (std::size_t k = VERVE_AGENT_DESC_SIZE_V2; k < sizeof memory; ++k) ASSERT_EQ(memory[k], 0xAB);
    d->num_actions = 2;
    verve_agent* agent = createOrFail(*d);
    verve_agent_desc full;
    verve_agent_desc_default(&full);
    ASSERT_EQ(verve_agent_get_desc(agent, &full), VERVE_OK);
    EXPECT_EQ(full.max_rbfs, 1000000u);

    unsigned char stats[sizeof(verve_agent_stats)];
    std::memset(stats, 0xCD, sizeof stats);
    auto* s = reinterpret_cast<verve_agent_stats*>(stats);
    s->struct_size = VERVE_AGENT_STATS_SIZE_V1;
    ASSERT_EQ(verve_agent_get_stats(agent, s), VERVE_OK) << lastError();
    for (std::size_t k = VERVE_AGENT_STATS_SIZE_V1; k < sizeof stats; ++k) ASSERT_EQ(stats[k], 0xCD);
    s->struct_size = VERVE_AGENT_STATS_SIZE_V1 + 4;
    EXPECT_EQ(verve_agent_get_stats(agent, s), VERVE_ERROR_INVALID_ARGUMENT);
    verve_agent_destroy(agent);
}

}  // namespace
}  // namespace verve::hardening
