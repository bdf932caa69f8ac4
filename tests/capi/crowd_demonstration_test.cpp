// Demonstrated continuous actions in a batch (verve_batch_update_demonstrated_continuous): separate
// agents and the bodies of a brain get exactly what single verve_agent_update_demonstrated_continuous
// and verve_agent_update calls in array order give them; packed values and offsets are the same;
// a bad value anywhere refuses the whole call and changes nothing.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "crowd_support.hpp"
#include "verve_c.h"

namespace {

using verve_crowd_test::makeBatch;
using verve_crowd_test::saved;

// One continuous sensor, 3 discrete actions and `continuousActions` values in [-1, 1] beside them.
verve_agent_desc steering(uint32_t continuousActions, uint64_t seed) {
    verve_agent_desc d;
    verve_agent_desc_init(&d, sizeof d);
    d.num_continuous_sensors = 1;
    d.num_actions = 3;
    d.num_continuous_actions = continuousActions;
    d.seed = seed;
    return d;
}

// Four agents: two separate (2 and 1 continuous actions) and two bodies of one brain (2 each).
struct Crowd {
    verve_brain* brain = nullptr;
    verve_agent* agents[4] = {};
    static constexpr uint32_t kCounts[4] = {2, 1, 2, 2};  // continuous actions per agent

    Crowd() {
        const verve_agent_desc two = steering(2, 5), one = steering(1, 6), body = steering(2, 7);
        EXPECT_EQ(verve_agent_create(&two, &agents[0]), VERVE_OK);
        EXPECT_EQ(verve_agent_create(&one, &agents[1]), VERVE_OK);
        EXPECT_EQ(verve_brain_create(&body, &brain), VERVE_OK);
        EXPECT_EQ(verve_brain_create_body(brain, &agents[2]), VERVE_OK);
        EXPECT_EQ(verve_brain_create_body(brain, &agents[3]), VERVE_OK);
    }
    ~Crowd() {
        for (auto* a : agents) verve_agent_destroy(a);
        verve_brain_destroy(brain);
    }
    std::string state() const {
        return saved(agents[0]) + saved(agents[1]) + saved(brain);
    }
};

// Step `step`'s inputs: agent 1 and (every third step) agent 2 choose, the others are shown an
// action and continuous values, packed back to back over every agent's count (7 values).
struct Inputs {
    float rewards[4], continuous[4], shownValues[7];
    uint32_t shown[4];

    explicit Inputs(int step) {
        for (int i = 0; i < 4; ++i) {
            rewards[i] = 0.1f * static_cast<float>((step + i) % 5) - 0.2f;
            continuous[i] = 0.15f * static_cast<float>((step * 3 + i) % 13) - 0.9f;
            shown[i] = static_cast<uint32_t>((step + i) % 3);
        }
        shown[1] = VERVE_AGENT_CHOOSES;
        if (step % 3 == 0) shown[2] = VERVE_AGENT_CHOOSES;
        for (int k = 0; k < 7; ++k) shownValues[k] = 0.25f * static_cast<float>((step + k) % 9) - 1.0f;
    }
};

}  // namespace

TEST(BatchDemonstratedContinuous, AreThoseOfSingleCallsInArrayOrderOnAnyThreadCount) {
    for (uint32_t workers : {1u, 2u, 3u, 8u}) {
        Crowd batched, single;
        verve_batch* batch = makeBatch(workers);
        for (int step = 0; step < 30; ++step) {
            const Inputs in(step);
            uint32_t actions[4] = {};
            ASSERT_EQ(verve_batch_update_demonstrated_continuous(batch, batched.agents, 4, in.rewards, nullptr, nullptr, 0,
                                                                 in.continuous, nullptr, 4, 0.1f, in.shown, in.shownValues,
                                                                 nullptr, 7, actions, nullptr),
                      VERVE_OK)
                << verve_last_error();
            uint32_t at = 0;
            for (int i = 0; i < 4; ++i) {
                const uint32_t n = Crowd::kCounts[i];
                uint32_t a = 99;
                if (in.shown[i] == VERVE_AGENT_CHOOSES) {
                    ASSERT_EQ(verve_agent_update(single.agents[i], in.rewards[i], nullptr, 0, &in.continuous[i], 1, 0.1f, &a),
                              VERVE_OK);
                } else {
                    ASSERT_EQ(verve_agent_update_demonstrated_continuous(single.agents[i], in.rewards[i], nullptr, 0,
                                                                         &in.continuous[i], 1, 0.1f, nullptr, 0,
                                                                         in.shown[i], &in.shownValues[at], n),
                              VERVE_OK)
                        << verve_last_error();
                    a = in.shown[i];
                    // The agent plays back the teacher's values, as after a single call.
                    float played[2] = {};
                    ASSERT_EQ(verve_agent_get_continuous_action(batched.agents[i], played, n), VERVE_OK);
                    for (uint32_t k = 0; k < n; ++k) EXPECT_EQ(played[k], in.shownValues[at + k]);
                }
                EXPECT_EQ(actions[i], a) << "workers " << workers << " step " << step << " agent " << i;
                at += n;
            }
        }
        EXPECT_EQ(batched.state(), single.state()) << "workers " << workers;
        verve_batch_destroy(batch);
    }
}

TEST(BatchDemonstratedContinuous, OffsetsReadTheSameValuesAsPacking) {
    Crowd packed, spaced;
    verve_batch* batch = makeBatch(2);
    const uint32_t offsets[4] = {10, 0, 4, 7};  // any order, with gaps
    for (int step = 0; step < 20; ++step) {
        const Inputs in(step);
        float spread[12] = {};
        const float* p = in.shownValues;
        for (int i = 0; i < 4; ++i) {
            for (uint32_t k = 0; k < Crowd::kCounts[i]; ++k) spread[offsets[i] + k] = *p++;
        }
        uint32_t a[4], b[4];
        ASSERT_EQ(verve_batch_update_demonstrated_continuous(batch, packed.agents, 4, in.rewards, nullptr, nullptr, 0,
                                                             in.continuous, nullptr, 4, 0.1f, in.shown, in.shownValues,
                                                             nullptr, 7, a, nullptr),
                  VERVE_OK);
        ASSERT_EQ(verve_batch_update_demonstrated_continuous(batch, spaced.agents, 4, in.rewards, nullptr, nullptr, 0,
                                                             in.continuous, nullptr, 4, 0.1f, in.shown, spread, offsets,
                                                             12, b, nullptr),
                  VERVE_OK)
            << verve_last_error();
        for (int i = 0; i < 4; ++i) EXPECT_EQ(a[i], b[i]);
    }
    EXPECT_EQ(packed.state(), spaced.state());
    verve_batch_destroy(batch);
}

// Without the values it is verve_batch_update_demonstrated: the policy's means are played.
TEST(BatchDemonstratedContinuous, WithoutValuesIsTheCallWithoutThem) {
    Crowd with, without;
    verve_batch* batch = makeBatch(2);
    for (int step = 0; step < 20; ++step) {
        const Inputs in(step);
        uint32_t a[4], b[4];
        ASSERT_EQ(verve_batch_update_demonstrated_continuous(batch, with.agents, 4, in.rewards, nullptr, nullptr, 0,
                                                             in.continuous, nullptr, 4, 0.1f, in.shown, nullptr, nullptr,
                                                             0, a, nullptr),
                  VERVE_OK);
        ASSERT_EQ(verve_batch_update_demonstrated(batch, without.agents, 4, in.rewards, nullptr, nullptr, 0, in.continuous,
                                                  nullptr, 4, 0.1f, in.shown, b, nullptr),
                  VERVE_OK);
    }
    EXPECT_EQ(with.state(), without.state());
    verve_batch_destroy(batch);
}

TEST(BatchDemonstratedContinuous, ABadValueAnywhereRefusesTheWholeCallAndChangesNothing) {
    Crowd crowd;
    verve_batch* batch = makeBatch(2);
    const Inputs warmUp(0);
    uint32_t actions[4];
    ASSERT_EQ(verve_batch_update_demonstrated_continuous(batch, crowd.agents, 4, warmUp.rewards, nullptr, nullptr, 0,
                                                         warmUp.continuous, nullptr, 4, 0.1f, warmUp.shown,
                                                         warmUp.shownValues, nullptr, 7, actions, nullptr),
              VERVE_OK);
    const std::string before = crowd.state();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    struct Case {
        const char* what;
        int index;      // which of the 7 values is spoiled (-1: none)
        float value;
        uint32_t total; // the array's length
        const char* agent;
    };
    // Agent 0's values are 0-1, agent 1's 2 (it chooses, never read), agent 2's 3-4, agent 3's 5-6.
    const Case cases[] = {{"above 1", 6, 1.5f, 7, "agents[3]"},
                          {"NaN", 0, nan, 7, "agents[0]"},
                          {"below -1", 4, -1.01f, 7, "agents[2]"},
                          {"array too short", -1, 0, 6, "agents[3]"}};
    Inputs in(1);  // agents 0, 2 and 3 shown
    ASSERT_NE(in.shown[2], VERVE_AGENT_CHOOSES);
    for (const Case& c : cases) {
        Inputs bad = in;
        if (c.index >= 0) bad.shownValues[c.index] = c.value;
        verve_result results[4];
        for (auto& a : actions) a = 77;
        EXPECT_EQ(verve_batch_update_demonstrated_continuous(batch, crowd.agents, 4, bad.rewards, nullptr, nullptr, 0,
                                                             bad.continuous, nullptr, 4, 0.1f, bad.shown,
                                                             bad.shownValues, nullptr, c.total, actions, results),
                  VERVE_ERROR_INVALID_ARGUMENT)
            << c.what;
        EXPECT_NE(std::string(verve_last_error()).find(c.agent), std::string::npos) << c.what << ": " << verve_last_error();
        for (auto a : actions) EXPECT_EQ(a, 77u) << c.what << ": actions written by a refused call";
        EXPECT_EQ(crowd.state(), before) << c.what;
    }
    // A value out of range where an agent chooses is never read.
    Inputs ignored = in;
    ignored.shownValues[2] = 5.0f;
    EXPECT_EQ(verve_batch_update_demonstrated_continuous(batch, crowd.agents, 4, ignored.rewards, nullptr, nullptr, 0,
                                                         ignored.continuous, nullptr, 4, 0.1f, ignored.shown,
                                                         ignored.shownValues, nullptr, 7, actions, nullptr),
              VERVE_OK)
        << verve_last_error();
    verve_batch_destroy(batch);
}
