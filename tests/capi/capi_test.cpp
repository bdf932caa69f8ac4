// The C ABI through the shared library, as a host sees it: result codes, messages, NULLs, bad
// counts and values that change nothing, struct sizes, memory saves, threads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "verve_c.h"

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

verve_agent_desc smallDesc() {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_discrete_sensors = 1;
    d.discrete_sensor_values[0] = 5;
    d.num_continuous_sensors = 1;
    d.num_actions = 3;
    d.seed = 42;
    return d;
}

std::string lastError() { return verve_last_error(); }

// verve_agent_create refuses `d` with a message that says `says`, and hands out nothing.
void expectRefusedSaying(const verve_agent_desc& d, const char* says) {
    verve_agent* agent = nullptr;
    EXPECT_EQ(verve_agent_create(&d, &agent), VERVE_ERROR_INVALID_ARGUMENT) << says;
    EXPECT_EQ(agent, nullptr);
    EXPECT_NE(lastError().find(says), std::string::npos) << lastError();
}

// An agent made by a host built against an older header: its struct of `size` bytes (followed by
// garbage the library must not read), shaped by `shape`. nullptr (and a failure) if refused.
template <typename Shape>
verve_agent* createFromOlderStruct(uint32_t size, Shape shape) {
    unsigned char memory[sizeof(verve_agent_desc)];
    std::memset(memory, 0xAB, sizeof memory);
    verve_agent_desc* d = reinterpret_cast<verve_agent_desc*>(memory);
    EXPECT_EQ(verve_agent_desc_init(d, size), VERVE_OK);
    shape(*d);
    verve_agent* agent = nullptr;
    EXPECT_EQ(verve_agent_create(d, &agent), VERVE_OK) << verve_last_error();
    return agent;
}

class CApi : public ::testing::Test {
protected:
    void SetUp() override {
        const verve_agent_desc d = smallDesc();
        ASSERT_EQ(verve_agent_create(&d, &agent_), VERVE_OK) << verve_last_error();
        for (int i = 0; i < 50; ++i) step(i % 5, static_cast<float>(i % 7) / 3.5f - 1.0f, 0.5f);
    }
    void TearDown() override { verve_agent_destroy(agent_); }

    uint32_t step(int32_t d, float c, float reward) {
        uint32_t action = 99;
        EXPECT_EQ(verve_agent_update(agent_, reward, &d, 1, &c, 1, 0.1f, &action), VERVE_OK) << verve_last_error();
        return action;
    }

    std::string saved() const {
        size_t size = 0;
        EXPECT_EQ(verve_agent_save_memory(agent_, nullptr, &size), VERVE_OK);
        std::string xml(size, '\0');
        EXPECT_EQ(verve_agent_save_memory(agent_, &xml[0], &size), VERVE_OK);
        return xml;
    }

    // A refused call must leave the agent exactly as it was.
    void expectRefusedUnchanged(verve_result expected, verve_result actual) {
        EXPECT_EQ(actual, expected) << verve_last_error();
        EXPECT_FALSE(lastError().empty());
    }

    verve_agent* agent_ = nullptr;
};

TEST(CApiLibrary, VersionAndResultNames) {
    EXPECT_EQ(verve_version(), static_cast<uint32_t>(VERVE_VERSION_NUMBER));
    EXPECT_STREQ(verve_result_name(VERVE_OK), "VERVE_OK");
    EXPECT_STREQ(verve_result_name(VERVE_ERROR_FORMAT), "VERVE_ERROR_FORMAT");
    EXPECT_STREQ(verve_result_name(VERVE_ERROR_INTERNAL), "VERVE_ERROR_INTERNAL");
    EXPECT_STREQ(verve_result_name(static_cast<verve_result>(15)), "VERVE_UNKNOWN_RESULT");
}

TEST(CApiLibrary, LastErrorIsClearedBySuccessAndNamesTheCall) {
    verve_agent* out = nullptr;
    EXPECT_EQ(verve_agent_create(nullptr, &out), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(lastError(), "verve_agent_create: desc is NULL");
    const verve_agent_desc d = smallDesc();
    ASSERT_EQ(verve_agent_create(&d, &out), VERVE_OK);
    EXPECT_EQ(lastError(), "");
    verve_agent_destroy(out);
}

TEST(CApiLibrary, LastErrorIsPerThread) {
    EXPECT_EQ(verve_agent_get_value(nullptr, nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    const std::string mine = lastError();
    std::string theirs = "unset";
    std::thread([&] { theirs = verve_last_error(); }).join();
    EXPECT_EQ(theirs, "");
    EXPECT_EQ(lastError(), mine);
}

TEST_F(CApi, NullPointersAreRefused) {
    const std::string before = saved();
    verve_agent_desc d = smallDesc();
    verve_agent* out = reinterpret_cast<verve_agent*>(0x1);  // must stay untouched
    float f = 0.0f;
    uint32_t u = 0;
    int i = 0;
    int32_t disc = 0;
    size_t size = 0;
    verve_agent_stats stats;
    stats.struct_size = sizeof stats;
    verve_value_axis axis = {VERVE_SENSOR_CONTINUOUS, 0, 4};
    float values[4];
    const uint8_t mask[3] = {1, 1, 1};

    const verve_result results[] = {
        verve_agent_desc_init(nullptr, sizeof d),
        verve_agent_create(nullptr, &out),
        verve_agent_create(&d, nullptr),
        verve_agent_update(nullptr, 0.0f, &disc, 1, &f, 1, 0.1f, &u),
        verve_agent_update(agent_, 0.0f, &disc, 1, &f, 1, 0.1f, nullptr),
        verve_agent_update(agent_, 0.0f, nullptr, 1, &f, 1, 0.1f, &u),
        verve_agent_update(agent_, 0.0f, &disc, 1, nullptr, 1, 0.1f, &u),
        verve_agent_end_episode(nullptr, 0.0f),
        verve_agent_truncate_episode(nullptr, 0.0f),
        verve_agent_update_masked(nullptr, 0.0f, &disc, 1, &f, 1, 0.1f, mask, 3, &u),
        verve_agent_update_masked(agent_, 0.0f, &disc, 1, &f, 1, 0.1f, nullptr, 3, &u),
        verve_agent_update_masked(agent_, 0.0f, &disc, 1, &f, 1, 0.1f, mask, 3, nullptr),
        verve_agent_set_action_selection(nullptr, VERVE_ACTION_GREEDY),
        verve_agent_get_action_selection(nullptr, &u),
        verve_agent_get_action_selection(agent_, nullptr),
        verve_agent_get_action_probabilities(nullptr, values, 3),
        verve_agent_get_action_probabilities(agent_, nullptr, 3),
        verve_agent_reset_short_term_memory(nullptr),
        verve_agent_set_learning(nullptr, 1),
        verve_agent_get_learning(nullptr, &i),
        verve_agent_get_learning(agent_, nullptr),
        verve_agent_get_desc(nullptr, &d),
        verve_agent_get_desc(agent_, nullptr),
        verve_agent_get_value(nullptr, &f),
        verve_agent_get_value(agent_, nullptr),
        verve_agent_get_td_error(nullptr, &f),
        verve_agent_get_td_error(agent_, nullptr),
        verve_agent_get_rbf_count(nullptr, &u),
        verve_agent_get_rbf_count(agent_, nullptr),
        verve_agent_get_stats(nullptr, &stats),
        verve_agent_get_stats(agent_, nullptr),
        verve_agent_sample_values(nullptr, &axis, 1, &disc, 1, &f, 1, values, 4),
        verve_agent_sample_values(agent_, nullptr, 1, &disc, 1, &f, 1, values, 4),
        verve_agent_sample_values(agent_, &axis, 1, nullptr, 1, &f, 1, values, 4),
        verve_agent_sample_values(agent_, &axis, 1, &disc, 1, nullptr, 1, values, 4),
        verve_agent_sample_values(agent_, &axis, 1, &disc, 1, &f, 1, nullptr, 4),
        verve_agent_save(nullptr, "x.xml"),
        verve_agent_save(agent_, nullptr),
        verve_agent_load(nullptr, &out),
        verve_agent_load("x.xml", nullptr),
        verve_agent_save_memory(nullptr, nullptr, &size),
        verve_agent_save_memory(agent_, nullptr, nullptr),
        verve_agent_save_binary(nullptr, "x.bin"),
        verve_agent_save_binary(agent_, nullptr),
        verve_agent_save_memory_binary(nullptr, nullptr, &size),
        verve_agent_save_memory_binary(agent_, nullptr, nullptr),
        verve_agent_load_memory(nullptr, 10, &out),
        verve_agent_load_memory("<x/>", 4, nullptr),
    };
    for (std::size_t k = 0; k < sizeof results / sizeof results[0]; ++k) {
        EXPECT_EQ(results[k], VERVE_ERROR_INVALID_ARGUMENT) << "call #" << k;
    }
    EXPECT_NE(lastError().find("NULL"), std::string::npos) << lastError();
    EXPECT_EQ(out, reinterpret_cast<verve_agent*>(0x1));
    verve_agent_destroy(nullptr);
    verve_agent_desc_default(nullptr);
    EXPECT_EQ(saved(), before);
}

TEST_F(CApi, DemonstratedStepsAreValidatedAndPullThePolicyTowardsTheirAction) {
    int32_t d = 1;
    float c = 0.3f;
    const uint8_t onlyFirst[3] = {1, 0, 0}, all[3] = {1, 1, 1};
    const std::string before = saved();
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT,
                           verve_agent_update_demonstrated(nullptr, 0.0f, &d, 1, &c, 1, 0.1f, nullptr, 0, 0));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT,
                           verve_agent_update_demonstrated(agent_, 0.0f, &d, 1, &c, 1, 0.1f, nullptr, 0, 3));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT,
                           verve_agent_update_demonstrated(agent_, 0.0f, &d, 1, &c, 1, 0.1f, onlyFirst, 3, 2));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT,
                           verve_agent_update_demonstrated(agent_, 0.0f, &d, 1, &c, 1, 0.1f, nullptr, 3, 0));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT,
                           verve_agent_update_demonstrated(agent_, kNaN, &d, 1, &c, 1, 0.1f, nullptr, 0, 0));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT,
                           verve_agent_update_demonstrated(agent_, 0.0f, nullptr, 1, &c, 1, 0.1f, nullptr, 0, 0));
    EXPECT_NE(lastError().find("NULL"), std::string::npos) << lastError();
    EXPECT_EQ(saved(), before);

    // Shown action 2 at one state, with no reward at all: the policy there comes to prefer it.
    for (int i = 0; i < 10; ++i) {
        ASSERT_EQ(verve_agent_update_demonstrated(agent_, 0.0f, &d, 1, &c, 1, 0.1f, i % 2 ? all : nullptr,
                                                  i % 2 ? 3 : 0, 2),
                  VERVE_OK)
            << verve_last_error();
    }
    uint32_t action = 99;
    ASSERT_EQ(verve_agent_update(agent_, 0.0f, &d, 1, &c, 1, 0.1f, &action), VERVE_OK);
    float p[3] = {0, 0, 0};
    ASSERT_EQ(verve_agent_get_action_probabilities(agent_, p, 3), VERVE_OK);
    EXPECT_GT(p[2], 0.75f) << p[0] << " " << p[1];  // uniform: 1/3; 0.87 measured
}

// fuzz_crowd found it: a demonstrated step moved the actor by the policy rate times at most 1,
// unclamped, so the largest policy_multiplier the descriptor allows (any finite one) put a weight
// at 1e37 in one step, and the agent could no longer be saved (weights beyond +-1e20 are refused
// as corrupt). Its steps are held to the TD steps' limit, as the critic's and actor's are.
TEST(CApiDemonstration, AHugePolicyMultiplierKeepsTheAgentSaveable) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_continuous_sensors = 1;
    d.num_actions = 5;
    d.policy_multiplier = 1.5e38f;
    verve_agent* agent = nullptr;
    ASSERT_EQ(verve_agent_create(&d, &agent), VERVE_OK) << verve_last_error();
    for (int i = 0; i < 20; ++i) {
        const float c = 0.1f * static_cast<float>(i % 3);
        ASSERT_EQ(verve_agent_update_demonstrated(agent, 0.0f, nullptr, 0, &c, 1, 0.1f, nullptr, 0, i % 5), VERVE_OK)
            << verve_last_error();
    }
    size_t size = 0;
    EXPECT_EQ(verve_agent_save_memory(agent, nullptr, &size), VERVE_OK) << verve_last_error();
    verve_agent_destroy(agent);
}

TEST_F(CApi, PraiseIsValidatedAndMovesThePolicyForTheActsBeforeIt) {
    const std::string before = saved();
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_teach(nullptr, 1.0f));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_teach(agent_, kNaN));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_teach(agent_, 1.5f));
    EXPECT_NE(lastError().find("[-1, 1]"), std::string::npos) << lastError();
    ASSERT_EQ(verve_agent_teach(agent_, 0.0f), VERVE_OK);  // arms the memory, judges nothing
    EXPECT_EQ(saved(), before);

    // An answer at one state, then half a second elsewhere, then the judgement: praised when the
    // answer was action 1, scolded otherwise.
    int32_t d = 1, elsewhere = 0;
    float c = -0.4f, far = 0.9f;
    uint32_t action = 0, answer = 0;
    for (int i = 0; i < 40; ++i) {
        ASSERT_EQ(verve_agent_update(agent_, 0.0f, &d, 1, &c, 1, 0.1f, &answer), VERVE_OK);
        for (int k = 0; k < 5; ++k) ASSERT_EQ(verve_agent_update(agent_, 0.0f, &elsewhere, 1, &far, 1, 0.1f, &action), VERVE_OK);
        ASSERT_EQ(verve_agent_teach(agent_, answer == 1 ? 1.0f : -1.0f), VERVE_OK) << verve_last_error();
        for (int k = 0; k < 20; ++k) ASSERT_EQ(verve_agent_update(agent_, 0.0f, &elsewhere, 1, &far, 1, 0.1f, &action), VERVE_OK);
    }
    ASSERT_EQ(verve_agent_update(agent_, 0.0f, &d, 1, &c, 1, 0.1f, &action), VERVE_OK);
    float p[3] = {0, 0, 0};
    ASSERT_EQ(verve_agent_get_action_probabilities(agent_, p, 3), VERVE_OK);
    EXPECT_GT(p[1], 0.75f) << p[0] << " " << p[2];
}

TEST_F(CApi, PolicyReadOutsGreedyModeMasksAndTruncation) {
    float p[3] = {0, 0, 0};
    ASSERT_EQ(verve_agent_get_action_probabilities(agent_, p, 3), VERVE_OK) << verve_last_error();
    EXPECT_NEAR(p[0] + p[1] + p[2], 1.0f, 1e-5f);
    const std::string before = saved();
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_get_action_probabilities(agent_, p, 2));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_set_action_selection(agent_, 2));
    int32_t d = 1;
    float c = 0.3f;
    uint32_t action = 99;
    const uint8_t none[3] = {0, 0, 0}, notFlag[3] = {1, 3, 0}, onlyLast[3] = {0, 0, 1};
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT,
                           verve_agent_update_masked(agent_, 0.0f, &d, 1, &c, 1, 0.1f, none, 3, &action));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT,
                           verve_agent_update_masked(agent_, 0.0f, &d, 1, &c, 1, 0.1f, notFlag, 3, &action));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT,
                           verve_agent_update_masked(agent_, 0.0f, &d, 1, &c, 1, 0.1f, onlyLast, 2, &action));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_truncate_episode(agent_, kNaN));
    EXPECT_EQ(action, 99u);
    EXPECT_EQ(saved(), before);

    for (int i = 0; i < 20; ++i) {
        ASSERT_EQ(verve_agent_update_masked(agent_, 0.0f, &d, 1, &c, 1, 0.1f, onlyLast, 3, &action), VERVE_OK);
        EXPECT_EQ(action, 2u);
    }
    ASSERT_EQ(verve_agent_get_action_probabilities(agent_, p, 3), VERVE_OK);
    EXPECT_EQ(p[0], 0.0f);
    EXPECT_FLOAT_EQ(p[2], 1.0f);
    EXPECT_EQ(verve_agent_truncate_episode(agent_, -0.5f), VERVE_OK) << verve_last_error();

    uint32_t mode = 99;
    ASSERT_EQ(verve_agent_get_action_selection(agent_, &mode), VERVE_OK);
    EXPECT_EQ(mode, uint32_t{VERVE_ACTION_SAMPLE});
    ASSERT_EQ(verve_agent_set_action_selection(agent_, VERVE_ACTION_GREEDY), VERVE_OK);
    ASSERT_EQ(verve_agent_get_action_selection(agent_, &mode), VERVE_OK);
    EXPECT_EQ(mode, uint32_t{VERVE_ACTION_GREEDY});
    ASSERT_EQ(verve_agent_set_learning(agent_, 0), VERVE_OK);
    const uint32_t first = step(d, c, 0.0f);
    ASSERT_EQ(verve_agent_get_action_probabilities(agent_, p, 3), VERVE_OK);
    for (uint32_t a = 0; a < 3; ++a) EXPECT_LE(p[a], p[first]);
    for (int i = 0; i < 20; ++i) EXPECT_EQ(step(d, c, 0.0f), first);  // deterministic
}

TEST(CApiDesc, PolicyWeightBoundReachesTheAgentAndIsValidated) {
    verve_agent_desc d = smallDesc();
    EXPECT_EQ(d.policy_weight_bound, 0.0f);
    d.policy_weight_bound = 6.0f;
    verve_agent* agent = nullptr;
    ASSERT_EQ(verve_agent_create(&d, &agent), VERVE_OK) << verve_last_error();
    verve_agent_desc back;
    verve_agent_desc_default(&back);
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.policy_weight_bound, 6.0f);
    verve_agent_destroy(agent);
    d.policy_weight_bound = -1.0f;
    EXPECT_EQ(verve_agent_create(&d, &agent), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("policy_weight_bound"), std::string::npos) << lastError();
    // A V2 host's struct ends before the field, whatever lies beyond it: the default applies.
    unsigned char memory[sizeof(verve_agent_desc)];
    std::memset(memory, 0xAB, sizeof memory);
    verve_agent_desc* v2 = reinterpret_cast<verve_agent_desc*>(memory);
    ASSERT_EQ(verve_agent_desc_init(v2, VERVE_AGENT_DESC_SIZE_V2), VERVE_OK);
    ASSERT_EQ(verve_agent_create(v2, &agent), VERVE_OK) << verve_last_error();
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.policy_weight_bound, 0.0f);
    verve_agent_destroy(agent);
}

TEST(CApiDesc, AdaptationReachesTheAgentAndUnknownBitsAreRefused) {
    verve_agent_desc d = smallDesc();
    EXPECT_EQ(d.adaptation, uint64_t{VERVE_ADAPT_ALL});  // the library's default
    d.adaptation = VERVE_ADAPT_HORIZON;
    verve_agent* agent = nullptr;
    ASSERT_EQ(verve_agent_create(&d, &agent), VERVE_OK) << verve_last_error();
    verve_agent_desc back;
    verve_agent_desc_default(&back);
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.adaptation, uint64_t{VERVE_ADAPT_HORIZON});
    verve_agent_destroy(agent);
    for (uint64_t bad : {uint64_t{128}, uint64_t{VERVE_ADAPT_ALL} | (uint64_t{1} << 40)}) {
        d.adaptation = bad;
        agent = nullptr;
        EXPECT_EQ(verve_agent_create(&d, &agent), VERVE_ERROR_INVALID_ARGUMENT) << bad;
        EXPECT_EQ(agent, nullptr);
        EXPECT_NE(lastError().find("adaptation"), std::string::npos) << lastError();
    }
    // A V3 host's struct ends before the field, whatever lies beyond it: the default applies.
    unsigned char memory[sizeof(verve_agent_desc)];
    std::memset(memory, 0xAB, sizeof memory);
    verve_agent_desc* v3 = reinterpret_cast<verve_agent_desc*>(memory);
    ASSERT_EQ(verve_agent_desc_init(v3, VERVE_AGENT_DESC_SIZE_V3), VERVE_OK);
    v3->num_actions = 2;
    ASSERT_EQ(verve_agent_create(v3, &agent), VERVE_OK) << verve_last_error();
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.adaptation, uint64_t{VERVE_ADAPT_ALL});
    verve_agent_destroy(agent);
}

TEST_F(CApi, BadObservationsChangeNothing) {
    const std::string before = saved();
    int32_t disc = 2;
    float cont = 0.5f;
    const int32_t badDisc[] = {5, -1};
    uint32_t action = 77;
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_update(agent_, 0.0f, &disc, 0, &cont, 1, 0.1f, &action));
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_update(agent_, 0.0f, &disc, 1, &cont, 2, 0.1f, &action));
    for (int32_t d : badDisc) {
        expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_update(agent_, 0.0f, &d, 1, &cont, 1, 0.1f, &action));
    }
    for (float bad : {kNaN, kInf, -kInf}) {
        expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_update(agent_, 0.0f, &disc, 1, &bad, 1, 0.1f, &action));
        expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_update(agent_, bad, &disc, 1, &cont, 1, 0.1f, &action));
        expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_update(agent_, 0.0f, &disc, 1, &cont, 1, bad, &action));
    }
    for (float dt : {0.0f, -0.1f}) {
        expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_update(agent_, 0.0f, &disc, 1, &cont, 1, dt, &action));
    }
    expectRefusedUnchanged(VERVE_ERROR_INVALID_ARGUMENT, verve_agent_end_episode(agent_, kNaN));
    EXPECT_EQ(action, 77u);
    EXPECT_EQ(saved(), before);
    // And the agent still works.
    EXPECT_LT(step(1, 0.0f, 0.0f), 3u);
    EXPECT_EQ(lastError(), "");
}

TEST_F(CApi, ReadOutsAndLearningSwitch) {
    verve_agent_stats stats;
    stats.struct_size = sizeof stats;
    ASSERT_EQ(verve_agent_get_stats(agent_, &stats), VERVE_OK);
    EXPECT_EQ(stats.steps, 50u);
    uint32_t rbfs = 0;
    ASSERT_EQ(verve_agent_get_rbf_count(agent_, &rbfs), VERVE_OK);
    EXPECT_EQ(rbfs, stats.rbf_count);
    EXPECT_GT(rbfs, 0u);
    float value = kNaN;
    ASSERT_EQ(verve_agent_get_value(agent_, &value), VERVE_OK);
    EXPECT_EQ(value, stats.value);
    stats.struct_size = sizeof stats - 4;
    EXPECT_EQ(verve_agent_get_stats(agent_, &stats), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("struct_size"), std::string::npos);

    int enabled = -1;
    ASSERT_EQ(verve_agent_get_learning(agent_, &enabled), VERVE_OK);
    EXPECT_EQ(enabled, 1);
    ASSERT_EQ(verve_agent_set_learning(agent_, 0), VERVE_OK);
    ASSERT_EQ(verve_agent_get_learning(agent_, &enabled), VERVE_OK);
    EXPECT_EQ(enabled, 0);
}

TEST_F(CApi, SampleValues) {
    const int32_t disc = 0;
    const float cont = 0.0f;
    verve_value_axis axes[2] = {{VERVE_SENSOR_CONTINUOUS, 0, 9}, {VERVE_SENSOR_DISCRETE, 0, 5}};
    std::vector<float> image(45, kNaN);
    ASSERT_EQ(verve_agent_sample_values(agent_, axes, 2, &disc, 1, &cont, 1, image.data(), 45), VERVE_OK) << verve_last_error();
    for (float v : image) EXPECT_TRUE(std::isfinite(v));
    EXPECT_EQ(verve_agent_sample_values(agent_, axes, 3, &disc, 1, &cont, 1, image.data(), 45), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_agent_sample_values(agent_, axes, 0, &disc, 1, &cont, 1, image.data(), 45), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_agent_sample_values(agent_, axes, 2, &disc, 1, &cont, 1, image.data(), 44), VERVE_ERROR_INVALID_ARGUMENT);
    axes[0].kind = 7;
    EXPECT_EQ(verve_agent_sample_values(agent_, axes, 1, &disc, 1, &cont, 1, image.data(), 9), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("kind"), std::string::npos);
}

// ---- descriptors and struct_size ----------------------------------------------------------

TEST(CApiDesc, SensorGroupsReachTheAgentAndAreValidated) {
    verve_agent_desc d = smallDesc();
    EXPECT_EQ(d.sensor_grouping, uint32_t{VERVE_GROUPING_AUTO});
    EXPECT_EQ(d.num_sensor_groups, 0u);
    d.num_continuous_sensors = 3;
    d.sensor_grouping = VERVE_GROUPING_CUSTOM;
    d.num_sensor_groups = 2;
    d.sensor_groups[0] = 0b011;
    d.sensor_groups[1] = 0b100;
    verve_agent* agent = nullptr;
    ASSERT_EQ(verve_agent_create(&d, &agent), VERVE_OK) << verve_last_error();
    verve_agent_desc back;
    verve_agent_desc_default(&back);
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.sensor_grouping, uint32_t{VERVE_GROUPING_CUSTOM});
    ASSERT_EQ(back.num_sensor_groups, 2u);
    EXPECT_EQ(back.sensor_groups[0], 0b011u);
    EXPECT_EQ(back.sensor_groups[1], 0b100u);
    const float obs[] = {0.2f, -0.4f, 0.9f};
    const int32_t disc[] = {1};
    uint32_t action = 0;
    ASSERT_EQ(verve_agent_update(agent, 0.0f, disc, 1, obs, 3, 0.1f, &action), VERVE_OK) << verve_last_error();
    verve_agent_stats stats;
    stats.struct_size = sizeof stats;
    ASSERT_EQ(verve_agent_get_stats(agent, &stats), VERVE_OK);
    EXPECT_EQ(stats.rbf_count, 2u);  // one RBF in each group
    verve_agent_destroy(agent);

    struct Bad {
        uint32_t grouping, count;
        uint64_t first;
        const char* says;
    };
    for (const Bad& bad : {Bad{3, 0, 0, "sensor_grouping must be"}, Bad{VERVE_GROUPING_CUSTOM, 65, 0b111, "num_sensor_groups is 65"},
                           Bad{VERVE_GROUPING_CUSTOM, 1, 0b011, "continuous sensor 2 is in none of sensor_groups"},
                           Bad{VERVE_GROUPING_CUSTOM, 1, 0b1000, "sensor_groups[0] names a continuous sensor"},
                           Bad{VERVE_GROUPING_AUTO, 1, 0b111, "sensor_groups is only read with Custom sensor_grouping"}}) {
        d.sensor_grouping = bad.grouping;
        d.num_sensor_groups = bad.count;
        d.sensor_groups[0] = bad.first;
        expectRefusedSaying(d, bad.says);
    }
    // A V4 host's struct ends before the fields: Auto, whatever lies beyond.
    agent = createFromOlderStruct(VERVE_AGENT_DESC_SIZE_V4, [](verve_agent_desc& v4) { v4.num_continuous_sensors = 8; });
    ASSERT_NE(agent, nullptr);
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.sensor_grouping, uint32_t{VERVE_GROUPING_AUTO});
    EXPECT_EQ(back.num_sensor_groups, 0u);
    verve_agent_destroy(agent);
}

TEST(CApiDesc, ActionBranchesReachTheAgentAndAreValidated) {
    verve_agent_desc d = smallDesc();
    EXPECT_EQ(d.num_action_branches, 0u);
    d.num_actions = 0;  // with branches: their product
    d.num_action_branches = 3;
    d.action_branches[0] = 3;
    d.action_branches[1] = 3;
    d.action_branches[2] = 2;
    verve_agent* agent = nullptr;
    ASSERT_EQ(verve_agent_create(&d, &agent), VERVE_OK) << verve_last_error();
    verve_agent_desc back;
    verve_agent_desc_default(&back);
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.num_actions, 18u);
    ASSERT_EQ(back.num_action_branches, 3u);
    EXPECT_EQ(back.action_branches[2], 2u);

    // Masks and probabilities: one flag or value per choice of each branch (3 + 3 + 2).
    const float obs[] = {0.2f};
    const int32_t disc[] = {1};
    const uint8_t mask[8] = {0, 0, 1, 1, 1, 1, 0, 1};
    uint32_t action = 0;
    ASSERT_EQ(verve_agent_update_masked(agent, 0.0f, disc, 1, obs, 1, 0.1f, mask, 8, &action), VERVE_OK) << verve_last_error();
    uint32_t choices[3] = {9, 9, 9};
    ASSERT_EQ(verve_agent_split_action(agent, action, choices, 3), VERVE_OK) << verve_last_error();
    EXPECT_EQ(choices[0], 2u);
    EXPECT_EQ(choices[2], 1u);
    uint32_t joined = 99;
    ASSERT_EQ(verve_agent_join_action(agent, choices, 3, &joined), VERVE_OK);
    EXPECT_EQ(joined, action);
    float p[8];
    ASSERT_EQ(verve_agent_get_action_probabilities(agent, p, 8), VERVE_OK) << verve_last_error();
    EXPECT_FLOAT_EQ(p[2], 1.0f);
    EXPECT_FLOAT_EQ(p[6] + p[7], 1.0f);
    EXPECT_EQ(verve_agent_get_action_probabilities(agent, p, 7), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_agent_update_masked(agent, 0.0f, disc, 1, obs, 1, 0.1f, mask, 7, &action), VERVE_ERROR_INVALID_ARGUMENT);
    const uint8_t noPace[8] = {1, 1, 1, 1, 1, 1, 0, 0};
    EXPECT_EQ(verve_agent_update_masked(agent, 0.0f, disc, 1, obs, 1, 0.1f, noPace, 8, &action), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("no choice of branch 2"), std::string::npos) << lastError();
    EXPECT_EQ(verve_agent_split_action(agent, 18, choices, 3), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_agent_split_action(agent, 0, choices, 2), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_agent_split_action(agent, 0, nullptr, 3), VERVE_ERROR_INVALID_ARGUMENT);
    const uint32_t tooFar[3] = {0, 3, 0};
    EXPECT_EQ(verve_agent_join_action(agent, tooFar, 3, &joined), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("choice 3 of branch 1 is out of range"), std::string::npos) << lastError();
    verve_agent_destroy(agent);

    struct Bad {
        uint32_t actions, count, first;
        const char* says;
    };
    for (const Bad& bad : {Bad{0, 9, 3, "num_action_branches is 9, at most 8"}, Bad{17, 3, 3, "num_actions must be the product"},
                           Bad{0, 3, 0, "action_branches[0] must be at least 1"}, Bad{0, 3, 4096, "above 4096"}}) {
        d.num_actions = bad.actions;
        d.num_action_branches = bad.count;
        d.action_branches[0] = bad.first;
        expectRefusedSaying(d, bad.says);
    }
    // A V5 host's struct ends before the fields: one action set, whatever lies beyond.
    agent = createFromOlderStruct(VERVE_AGENT_DESC_SIZE_V5, [](verve_agent_desc& v5) { v5.num_actions = 4; });
    ASSERT_NE(agent, nullptr);
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.num_action_branches, 0u);
    EXPECT_EQ(back.num_actions, 4u);
    ASSERT_EQ(verve_agent_split_action(agent, 3, choices, 1), VERVE_OK);
    EXPECT_EQ(choices[0], 3u);
    verve_agent_destroy(agent);
}

TEST(CApiDesc, ContinuousActionsReachTheAgentAndAreValidated) {
    verve_agent_desc d = smallDesc();
    EXPECT_EQ(d.num_continuous_actions, 0u);
    d.num_actions = 0;  // continuous actions only: the one discrete action they keep
    d.num_continuous_actions = 2;
    verve_agent* agent = nullptr;
    ASSERT_EQ(verve_agent_create(&d, &agent), VERVE_OK) << verve_last_error();
    verve_agent_desc back;
    verve_agent_desc_default(&back);
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.num_actions, 1u);
    EXPECT_EQ(back.num_continuous_actions, 2u);

    float values[2] = {9.0f, 9.0f};
    ASSERT_EQ(verve_agent_get_continuous_action(agent, values, 2), VERVE_OK) << verve_last_error();
    EXPECT_EQ(values[0], 0.0f);  // before any update
    const float obs[] = {0.2f};
    const int32_t disc[] = {1};
    uint32_t action = 9;
    for (int t = 0; t < 20; ++t) {
        ASSERT_EQ(verve_agent_update(agent, -0.1f, disc, 1, obs, 1, 0.05f, &action), VERVE_OK) << verve_last_error();
        EXPECT_EQ(action, 0u);
        ASSERT_EQ(verve_agent_get_continuous_action(agent, values, 2), VERVE_OK);
        for (float v : values) EXPECT_TRUE(v >= -1.0f && v <= 1.0f) << v;
    }
    EXPECT_EQ(verve_agent_get_continuous_action(agent, values, 1), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("the agent has 2 continuous actions"), std::string::npos) << lastError();
    EXPECT_EQ(verve_agent_get_continuous_action(agent, nullptr, 2), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_agent_get_continuous_action(nullptr, values, 2), VERVE_ERROR_INVALID_ARGUMENT);
    float probability = 0.0f;
    ASSERT_EQ(verve_agent_get_action_probabilities(agent, &probability, 1), VERVE_OK);
    EXPECT_EQ(probability, 1.0f);

    // Saved and loaded (XML and binary, with short-term memory): the same next values.
    for (const bool binary : {false, true}) {
        std::vector<char> bytes(1 << 20);
        size_t size = bytes.size();
        ASSERT_EQ(binary ? verve_agent_save_memory_binary(agent, bytes.data(), &size)
                         : verve_agent_save_memory(agent, bytes.data(), &size),
                  VERVE_OK)
            << verve_last_error();
        verve_agent* loaded = nullptr;
        ASSERT_EQ(verve_agent_load_memory(bytes.data(), size, &loaded), VERVE_OK) << verve_last_error();
        float a[2], b[2];
        for (int t = 0; t < 10; ++t) {
            ASSERT_EQ(verve_agent_update(agent, 0.1f, disc, 1, obs, 1, 0.05f, &action), VERVE_OK);
            ASSERT_EQ(verve_agent_update(loaded, 0.1f, disc, 1, obs, 1, 0.05f, &action), VERVE_OK);
            ASSERT_EQ(verve_agent_get_continuous_action(agent, a, 2), VERVE_OK);
            ASSERT_EQ(verve_agent_get_continuous_action(loaded, b, 2), VERVE_OK);
            EXPECT_EQ(std::memcmp(a, b, sizeof a), 0) << (binary ? "binary" : "XML");
        }
        verve_agent_destroy(loaded);
    }
    verve_agent_destroy(agent);

    d.num_continuous_actions = 9;
    expectRefusedSaying(d, "num_continuous_actions is 9, at most 8");
    d.num_continuous_actions = uint64_t{1} << 32;  // not truncated into range
    expectRefusedSaying(d, "num_continuous_actions is 4294967296, at most 8");
    d.num_continuous_actions = 1;
    d.planning = 1;
    expectRefusedSaying(d, "planning needs discrete actions only");
    // A V6 host's struct ends before the field: no continuous actions, whatever lies beyond.
    agent = createFromOlderStruct(VERVE_AGENT_DESC_SIZE_V6, [](verve_agent_desc& v6) { v6.num_actions = 4; });
    ASSERT_NE(agent, nullptr);
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.num_continuous_actions, 0u);
    EXPECT_EQ(verve_agent_get_continuous_action(agent, values, 0), VERVE_OK);
    verve_agent_destroy(agent);
}

TEST(CApiDesc, DefaultsMatchTheDocumentedOnes) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    EXPECT_EQ(d.struct_size, sizeof d);
    EXPECT_EQ(d.resolution, 10u);
    EXPECT_FLOAT_EQ(d.tau_value, 0.1f);
    EXPECT_FLOAT_EQ(d.tau_discount, 1.0f);
    EXPECT_FLOAT_EQ(d.policy_multiplier, 5.0f);
    EXPECT_EQ(d.max_planning_steps, 10u);
    EXPECT_FLOAT_EQ(d.planning_uncertainty_threshold, 0.5f);
    EXPECT_FLOAT_EQ(d.curiosity_factor, 5.0f);
    EXPECT_EQ(d.planning_accumulates_uncertainty, 1u);
    EXPECT_EQ(d.learn_from_real_steps, 1u);
    EXPECT_EQ(d.discrete_prediction, static_cast<uint32_t>(VERVE_DISCRETE_PREDICTION_CATEGORICAL));
}

TEST(CApiDesc, PlanningVariantsReachTheAgent) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_discrete_sensors = 1;
    d.discrete_sensor_values[0] = 4;
    d.planning = 1;
    d.planning_accumulates_uncertainty = 0;
    d.learn_from_real_steps = 0;
    d.discrete_prediction = VERVE_DISCRETE_PREDICTION_ORDINAL;
    verve_agent* agent = nullptr;
    ASSERT_EQ(verve_agent_create(&d, &agent), VERVE_OK) << verve_last_error();
    verve_agent_desc back;
    verve_agent_desc_default(&back);
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK);
    EXPECT_EQ(back.planning_accumulates_uncertainty, 0u);
    EXPECT_EQ(back.learn_from_real_steps, 0u);
    EXPECT_EQ(back.discrete_prediction, static_cast<uint32_t>(VERVE_DISCRETE_PREDICTION_ORDINAL));
    verve_agent_destroy(agent);
    d.discrete_prediction = 2;
    EXPECT_EQ(verve_agent_create(&d, &agent), VERVE_ERROR_INVALID_ARGUMENT);
}

TEST(CApiDesc, AnOldSmallerStructIsAcceptedAndTheRestDefaulted) {
    // An old host's struct ends after `seed`; the bytes beyond it are not its own (here: garbage).
    unsigned char memory[sizeof(verve_agent_desc)];
    std::memset(memory, 0xAB, sizeof memory);
    verve_agent_desc* d = reinterpret_cast<verve_agent_desc*>(memory);
    ASSERT_EQ(verve_agent_desc_init(d, VERVE_AGENT_DESC_SIZE_V1), VERVE_OK);
    for (std::size_t k = VERVE_AGENT_DESC_SIZE_V1; k < sizeof memory; ++k) ASSERT_EQ(memory[k], 0xAB) << "byte " << k;
    EXPECT_EQ(d->struct_size, VERVE_AGENT_DESC_SIZE_V1);
    d->num_actions = 4;

    verve_agent* agent = nullptr;
    ASSERT_EQ(verve_agent_create(d, &agent), VERVE_OK) << verve_last_error();
    verve_agent_desc full;
    verve_agent_desc_default(&full);
    ASSERT_EQ(verve_agent_get_desc(agent, &full), VERVE_OK);
    EXPECT_EQ(full.num_actions, 4u);
    EXPECT_EQ(full.planning, 0u);  // defaults, not the 0xAB garbage
    EXPECT_EQ(full.max_planning_steps, 10u);
    EXPECT_FLOAT_EQ(full.curiosity_factor, 5.0f);

    // get_desc into an old struct writes only its bytes.
    std::memset(memory, 0xCD, sizeof memory);
    d->struct_size = VERVE_AGENT_DESC_SIZE_V1;
    ASSERT_EQ(verve_agent_get_desc(agent, d), VERVE_OK);
    EXPECT_EQ(d->num_actions, 4u);
    for (std::size_t k = VERVE_AGENT_DESC_SIZE_V1; k < sizeof memory; ++k) ASSERT_EQ(memory[k], 0xCD) << "byte " << k;
    verve_agent_destroy(agent);
}

TEST(CApiDesc, GarbageStructSizesAreRefused) {
    for (uint32_t size : {0u, 4u, VERVE_AGENT_DESC_SIZE_V1 - 8, VERVE_AGENT_DESC_SIZE_V1 + 4,
                          VERVE_AGENT_DESC_SIZE_V2 + 4, VERVE_AGENT_DESC_SIZE_V3 + 4,
                          VERVE_AGENT_DESC_SIZE_V4 + 8, VERVE_AGENT_DESC_SIZE_V5 + 8, VERVE_AGENT_DESC_SIZE_V6 + 4,
                          VERVE_AGENT_DESC_SIZE_V7 + 8,
                          0xFFFFFFFFu}) {
        verve_agent_desc d = smallDesc();
        d.struct_size = size;
        verve_agent* out = nullptr;
        EXPECT_EQ(verve_agent_create(&d, &out), VERVE_ERROR_INVALID_ARGUMENT) << size;
        EXPECT_EQ(out, nullptr);
        EXPECT_NE(lastError().find("struct_size"), std::string::npos);
        EXPECT_EQ(verve_agent_desc_init(&d, size), VERVE_ERROR_INVALID_ARGUMENT) << size;
    }
}

TEST(CApiDesc, BadFieldsAreRefusedWithTheirName) {
    struct Case {
        void (*edit)(verve_agent_desc&);
        const char* name;
    };
    const Case cases[] = {
        {[](verve_agent_desc& d) { d.num_discrete_sensors = 65; }, "num_discrete_sensors"},
        {[](verve_agent_desc& d) { d.num_continuous_sensors = 99; }, "num_continuous_sensors"},
        {[](verve_agent_desc& d) { d.continuous_sensor_circular[0] = 2; }, "circular"},
        {[](verve_agent_desc& d) { d.rbf_allocation = 5; }, "rbf_allocation"},
        {[](verve_agent_desc& d) { d.planning = 2; }, "planning"},
        {[](verve_agent_desc& d) { d.curiosity = 3; }, "curiosity"},
        {[](verve_agent_desc& d) { d.num_actions = 0; }, "num_actions"},
        {[](verve_agent_desc& d) { d.discrete_sensor_values[0] = 0; }, "discrete_sensor_values[0]"},
        {[](verve_agent_desc& d) { d.tau_value = kNaN; }, "tau_value"},
        {[](verve_agent_desc& d) { d.trace_threshold = 0.0f; }, "trace_threshold"},
    };
    for (const Case& c : cases) {
        verve_agent_desc d = smallDesc();
        c.edit(d);
        verve_agent* out = nullptr;
        EXPECT_EQ(verve_agent_create(&d, &out), VERVE_ERROR_INVALID_ARGUMENT) << c.name;
        EXPECT_EQ(out, nullptr);
        EXPECT_NE(lastError().find(c.name), std::string::npos) << lastError();
    }
}

// ---- persistence ---------------------------------------------------------------------------

TEST_F(CApi, MemorySaveTwoCallPattern) {
    size_t size = 0;
    ASSERT_EQ(verve_agent_save_memory(agent_, nullptr, &size), VERVE_OK);
    ASSERT_GT(size, 100u);
    std::vector<char> small(size - 1, 'z');
    size_t smallSize = small.size();
    EXPECT_EQ(verve_agent_save_memory(agent_, small.data(), &smallSize), VERVE_ERROR_BUFFER_TOO_SMALL);
    EXPECT_EQ(smallSize, size);
    EXPECT_EQ(small.back(), 'z');  // nothing written
    std::vector<char> buffer(size + 10, 'z');
    size_t bufferSize = buffer.size();
    ASSERT_EQ(verve_agent_save_memory(agent_, buffer.data(), &bufferSize), VERVE_OK);
    EXPECT_EQ(bufferSize, size);

    verve_agent* loaded = nullptr;
    ASSERT_EQ(verve_agent_load_memory(buffer.data(), bufferSize, &loaded), VERVE_OK) << verve_last_error();
    // Same state: same actions from here on.
    for (int i = 0; i < 100; ++i) {
        const int32_t d = i % 5;
        const float c = std::sin(static_cast<float>(i));
        uint32_t a1 = 0, a2 = 1;
        ASSERT_EQ(verve_agent_update(agent_, 0.1f, &d, 1, &c, 1, 0.1f, &a1), VERVE_OK);
        ASSERT_EQ(verve_agent_update(loaded, 0.1f, &d, 1, &c, 1, 0.1f, &a2), VERVE_OK);
        ASSERT_EQ(a1, a2) << "step " << i;
    }
    verve_agent_destroy(loaded);
}

std::string binarySaveOf(const verve_agent* agent) {
    size_t size = 0;
    EXPECT_EQ(verve_agent_save_memory_binary(agent, nullptr, &size), VERVE_OK) << verve_last_error();
    std::string bytes(size, '\0');
    EXPECT_EQ(verve_agent_save_memory_binary(agent, &bytes[0], &size), VERVE_OK) << verve_last_error();
    bytes.resize(size);
    return bytes;
}

TEST_F(CApi, BinarySaveLoadsBackToTheSameAgent) {
    const std::string bytes = binarySaveOf(agent_);
    ASSERT_EQ(bytes.compare(0, 8, "VERVEBIN"), 0);
    EXPECT_LT(bytes.size(), saved().size());
    size_t tooSmall = bytes.size() - 1;
    std::string small(tooSmall, 'z');
    EXPECT_EQ(verve_agent_save_memory_binary(agent_, &small[0], &tooSmall), VERVE_ERROR_BUFFER_TOO_SMALL);
    EXPECT_EQ(tooSmall, bytes.size());
    EXPECT_EQ(small, std::string(small.size(), 'z'));

    verve_agent* loaded = nullptr;
    ASSERT_EQ(verve_agent_load_memory(bytes.data(), bytes.size(), &loaded), VERVE_OK) << verve_last_error();
    EXPECT_EQ(binarySaveOf(loaded), bytes);
    std::string xml(1 << 20, '\0');
    size_t xmlSize = xml.size();
    ASSERT_EQ(verve_agent_save_memory(loaded, &xml[0], &xmlSize), VERVE_OK);
    xml.resize(xmlSize);
    EXPECT_EQ(xml, saved());  // the same agent as the original's XML says
    verve_agent_destroy(loaded);

    std::string corrupt = bytes;
    corrupt[corrupt.size() / 2] = static_cast<char>(corrupt[corrupt.size() / 2] ^ 1);
    verve_agent* none = nullptr;
    EXPECT_EQ(verve_agent_load_memory(corrupt.data(), corrupt.size(), &none), VERVE_ERROR_FORMAT);
    EXPECT_NE(lastError().find("checksum"), std::string::npos) << lastError();
    EXPECT_EQ(none, nullptr);
}

// A size query in one format never hands its kept bytes to a call in the other.
TEST_F(CApi, KeptSaveBytesAreDeliveredOnlyInTheirFormat) {
    const std::string xml = saved();
    const std::string binary = binarySaveOf(agent_);
    size_t size = 0;
    ASSERT_EQ(verve_agent_save_memory(agent_, nullptr, &size), VERVE_OK);
    std::string out(xml.size() + binary.size(), '\0');
    size = out.size();
    ASSERT_EQ(verve_agent_save_memory_binary(agent_, &out[0], &size), VERVE_OK);
    EXPECT_EQ(out.substr(0, size), binary);
    ASSERT_EQ(verve_agent_save_memory_binary(agent_, nullptr, &size), VERVE_OK);
    size = out.size();
    ASSERT_EQ(verve_agent_save_memory(agent_, &out[0], &size), VERVE_OK);
    EXPECT_EQ(out.substr(0, size), xml);
}

// The size query keeps the bytes it serialised for the call with a buffer; any change to an agent
// in between must give the agent as it is now, never the kept bytes.
TEST_F(CApi, MemorySaveAfterAChangeIsTheAgentAsItIsNow) {
    const std::vector<std::function<void()>> changes = {
        [&] { step(1, 0.3f, 1.0f); },
        [&] { ASSERT_EQ(verve_agent_end_episode(agent_, -1.0f), VERVE_OK); },
        [&] { ASSERT_EQ(verve_agent_set_learning(agent_, 0), VERVE_OK); },
        [&] { ASSERT_EQ(verve_agent_set_learning(agent_, 1), VERVE_OK); },
        [&] { ASSERT_EQ(verve_agent_reset_short_term_memory(agent_), VERVE_OK); },
    };
    for (std::size_t i = 0; i < changes.size(); ++i) {
        step(static_cast<int32_t>(i), 0.1f, 0.5f);  // live traces and a previous state to change
        size_t before = 0;
        ASSERT_EQ(verve_agent_save_memory(agent_, nullptr, &before), VERVE_OK);
        const std::string was = saved();
        ASSERT_EQ(verve_agent_save_memory(agent_, nullptr, &before), VERVE_OK);
        changes[i]();
        std::string now(before + 4096, '\0');
        size_t size = now.size();
        ASSERT_EQ(verve_agent_save_memory(agent_, &now[0], &size), VERVE_OK) << "change " << i;
        now.resize(size);
        EXPECT_NE(now, was) << "change " << i << " served the save from before it";
        EXPECT_EQ(now, saved()) << "change " << i;
    }
    // A change to another agent also drops the kept bytes (agents may share state); the save stays right.
    verve_agent* other = nullptr;
    const verve_agent_desc d = smallDesc();
    ASSERT_EQ(verve_agent_create(&d, &other), VERVE_OK);
    size_t size = 0;
    ASSERT_EQ(verve_agent_save_memory(agent_, nullptr, &size), VERVE_OK);
    const int32_t disc = 0;
    const float cont = 0.0f;
    uint32_t action = 0;
    ASSERT_EQ(verve_agent_update(other, 0.0f, &disc, 1, &cont, 1, 0.1f, &action), VERVE_OK);
    std::string xml(size, '\0');
    ASSERT_EQ(verve_agent_save_memory(agent_, &xml[0], &size), VERVE_OK);
    EXPECT_EQ(xml, saved());
    verve_agent_destroy(other);
}

TEST_F(CApi, BadSavesGiveFormatOrVersionErrorsAndNoAgent) {
    std::string xml = saved();
    verve_agent* out = reinterpret_cast<verve_agent*>(0x1);
    EXPECT_EQ(verve_agent_load_memory(xml.data(), xml.size() / 2, &out), VERVE_ERROR_FORMAT);
    EXPECT_NE(lastError().find("truncated"), std::string::npos) << lastError();
    EXPECT_EQ(verve_agent_load_memory(xml.data(), 0, &out), VERVE_ERROR_FORMAT);
    const std::string future = std::string(xml).replace(xml.find("format_version=\"1\""), 18, "format_version=\"9\"");
    EXPECT_EQ(verve_agent_load_memory(future.data(), future.size(), &out), VERVE_ERROR_VERSION);
    EXPECT_NE(lastError().find("version 9"), std::string::npos) << lastError();
    EXPECT_EQ(out, reinterpret_cast<verve_agent*>(0x1));
}

TEST_F(CApi, FileSaveAndLoad) {
    const std::string path = ::testing::TempDir() + "verve_capi_test.xml";
    ASSERT_EQ(verve_agent_save(agent_, path.c_str()), VERVE_OK) << verve_last_error();
    verve_agent* loaded = nullptr;
    ASSERT_EQ(verve_agent_load(path.c_str(), &loaded), VERVE_OK) << verve_last_error();
    size_t a = 0, b = 0;
    verve_agent_save_memory(agent_, nullptr, &a);
    verve_agent_save_memory(loaded, nullptr, &b);
    EXPECT_EQ(a, b);
    verve_agent_destroy(loaded);
    std::remove(path.c_str());

    EXPECT_EQ(verve_agent_save(agent_, "/no/such/dir/agent.xml"), VERVE_ERROR_IO);
    EXPECT_NE(lastError().find("/no/such/dir/agent.xml"), std::string::npos) << lastError();
    verve_agent* out = nullptr;
    EXPECT_EQ(verve_agent_load("/no/such/file.xml", &out), VERVE_ERROR_IO);
    EXPECT_EQ(out, nullptr);
}

TEST_F(CApi, BinaryFileSaveAndLoad) {
    const std::string path = ::testing::TempDir() + "verve_capi_test.bin";
    ASSERT_EQ(verve_agent_save_binary(agent_, path.c_str()), VERVE_OK) << verve_last_error();
    verve_agent* loaded = nullptr;
    ASSERT_EQ(verve_agent_load(path.c_str(), &loaded), VERVE_OK) << verve_last_error();
    EXPECT_EQ(binarySaveOf(loaded), binarySaveOf(agent_));
    verve_agent_destroy(loaded);
    std::remove(path.c_str());
    EXPECT_EQ(verve_agent_save_binary(agent_, "/no/such/dir/agent.bin"), VERVE_ERROR_IO);
    EXPECT_NE(lastError().find("/no/such/dir/agent.bin"), std::string::npos) << lastError();
}

// ---- threads -------------------------------------------------------------------------------

// Different agents may be used concurrently: each thread's agent must end exactly as it would alone.
TEST(CApiThreads, DifferentAgentsConcurrently) {
    auto run = [](uint64_t seed) {
        verve_agent_desc d = smallDesc();
        d.seed = seed;
        verve_agent* agent = nullptr;
        EXPECT_EQ(verve_agent_create(&d, &agent), VERVE_OK);
        uint64_t checksum = 0;
        for (int i = 0; i < 3000; ++i) {
            const int32_t disc = (i * 7) % 5;
            const float c = std::sin(0.37f * static_cast<float>(i));
            uint32_t action = 0;
            EXPECT_EQ(verve_agent_update(agent, disc == 2 ? 1.0f : -0.1f, &disc, 1, &c, 1, 0.1f, &action), VERVE_OK);
            checksum = checksum * 31 + action;
        }
        verve_agent_destroy(agent);
        return checksum;
    };
    std::vector<uint64_t> alone;
    for (uint64_t s = 1; s <= 4; ++s) alone.push_back(run(s));
    std::vector<uint64_t> together(4);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < 4; ++t) threads.emplace_back([&, t] { together[t] = run(t + 1); });
    for (auto& th : threads) th.join();
    EXPECT_EQ(alone, together);
}

}  // namespace
