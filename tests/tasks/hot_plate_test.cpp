#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "tasks/hot_plate.hpp"

using namespace verve::tasks;

TEST(HotPlate1D, EndsAreSafeAndTerminalEverythingElseHurts) {
    HotPlate plate({1, false, Sensors::Discrete});
    plate.place({2, 0}, 0);
    EXPECT_EQ(plate.optimalSteps(), 2u);
    StepResult r = plate.act(0);  // left
    EXPECT_FLOAT_EQ(r.reward, -1.0f);
    EXPECT_FALSE(r.terminal);
    r = plate.act(2);  // stay
    EXPECT_FLOAT_EQ(r.reward, -1.0f);
    EXPECT_EQ(plate.position(), (Cell{1, 0}));
    r = plate.act(0);
    EXPECT_FLOAT_EQ(r.reward, 1.0f);
    EXPECT_TRUE(r.terminal);
    EXPECT_TRUE(plate.succeeded());

    plate.place({17, 0}, 0);
    EXPECT_EQ(plate.optimalSteps(), 2u);
    plate.act(1);
    EXPECT_TRUE(plate.act(1).terminal);
}

TEST(HotPlate1D, SettingsAreTheThesis) {
    const verve::AgentDescriptor d = HotPlate({1, false, Sensors::Discrete}).agentDescriptor();
    EXPECT_EQ(d.discreteSensors, (std::vector<std::uint32_t>{20}));
    EXPECT_EQ(d.numActions, 3u);
    EXPECT_FLOAT_EQ(d.policyMultiplier, 10.0f);
    EXPECT_FLOAT_EQ(d.tauValue, 0.1f);
    const verve::AgentDescriptor c = HotPlate({1, false, Sensors::Continuous}).agentDescriptor();
    EXPECT_TRUE(c.discreteSensors.empty());
    EXPECT_EQ(c.continuousSensors.size(), 1u);
    EXPECT_EQ(c.resolution, 10u);
    const verve::AgentDescriptor s = HotPlate({1, true, Sensors::Continuous}).agentDescriptor();
    EXPECT_EQ(s.discreteSensors, (std::vector<std::uint32_t>{2}));
    EXPECT_EQ(s.resolution, 25u);
}

TEST(HotPlate1D, ContinuousObservationMapsCells) {
    HotPlate plate({1, false, Sensors::Continuous});
    verve::Observation obs(plate.agentDescriptor());
    plate.place({0, 0}, 0);
    plate.observe(obs);
    EXPECT_FLOAT_EQ(obs.continuous[0], -1.0f);
    plate.place({19, 0}, 0);
    plate.observe(obs);
    EXPECT_FLOAT_EQ(obs.continuous[0], 1.0f);
}

TEST(SignaledHotPlate1D, OnlyTheSignaledEndIsSafe) {
    HotPlate plate({1, true, Sensors::Discrete});
    verve::Observation obs(plate.agentDescriptor());
    plate.place({1, 0}, 1);  // safe zone on the right
    plate.observe(obs);
    EXPECT_EQ(obs.discrete[0], 1);
    EXPECT_EQ(obs.discrete[1], 1);
    EXPECT_EQ(plate.optimalSteps(), 18u);
    const StepResult r = plate.act(0);  // onto the left end: hot, not terminal
    EXPECT_EQ(plate.position(), (Cell{0, 0}));
    EXPECT_FLOAT_EQ(r.reward, -1.0f);
    EXPECT_FALSE(r.terminal);
    plate.place({1, 0}, 0);
    EXPECT_TRUE(plate.act(0).terminal);
}

TEST(HotPlate2D, EveryBorderIsSafeAndDistanceIsToTheNearest) {
    HotPlate plate({2, false, Sensors::Discrete});
    EXPECT_EQ(plate.agentDescriptor().numActions, 5u);
    plate.place({5, 2}, 0);
    EXPECT_EQ(plate.optimalSteps(), 2u);
    EXPECT_FALSE(plate.act(2).terminal);  // up
    const StepResult r = plate.act(2);
    EXPECT_TRUE(r.terminal);
    EXPECT_FLOAT_EQ(r.reward, 1.0f);
    plate.place({10, 10}, 0);
    EXPECT_EQ(plate.optimalSteps(), 9u);
    plate.place({18, 12}, 0);
    EXPECT_EQ(plate.optimalSteps(), 1u);
    EXPECT_TRUE(plate.act(1).terminal);  // right
}

TEST(SignaledHotPlate2D, FourSignalsNameFourBorders) {
    HotPlate plate({2, true, Sensors::Continuous});
    const verve::AgentDescriptor d = plate.agentDescriptor();
    EXPECT_EQ(d.discreteSensors, (std::vector<std::uint32_t>{4}));
    EXPECT_EQ(d.continuousSensors.size(), 2u);
    const Cell c{3, 6};
    const std::uint32_t expected[4] = {3, 16, 6, 13};
    for (int s = 0; s < 4; ++s) {
        plate.place(c, s);
        EXPECT_EQ(plate.optimalSteps(), expected[s]) << "signal " << s;
    }
    plate.place({1, 1}, 3);  // bottom is safe: the top border is hot
    EXPECT_FALSE(plate.act(2).terminal);
    EXPECT_FALSE(plate.act(0).terminal);
    EXPECT_EQ(plate.position(), (Cell{0, 0}));
}

TEST(HotPlate, StartsCoverEveryCellAndSafeStartsAreFinished) {
    HotPlate plate({1, false, Sensors::Discrete});
    std::set<int> starts;
    int finished = 0;
    for (std::uint64_t seed = 0; seed < 2000; ++seed) {
        plate.beginTrial(seed);
        starts.insert(plate.position().x);
        EXPECT_EQ(plate.finishedAtStart(), plate.position().x == 0 || plate.position().x == 19);
        finished += plate.finishedAtStart() ? 1 : 0;
    }
    EXPECT_EQ(starts.size(), 20u);
    EXPECT_GT(finished, 100);  // about 10% of starts
    EXPECT_LT(finished, 300);
}

TEST(HotPlate, SameSeedSameTrial) {
    HotPlate a({2, true, Sensors::Discrete});
    HotPlate b({2, true, Sensors::Discrete});
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        a.beginTrial(seed);
        b.beginTrial(seed);
        EXPECT_EQ(a.position(), b.position());
        EXPECT_EQ(a.signal(), b.signal());
    }
}

// The original's hot-plate tests cut a trial off after 200 steps; the numbers we compare with
// were measured that way.
TEST(HotPlate, TrialsAreCutOffAfter200StepsLikeTheOriginal) {
    EXPECT_EQ(HotPlate({1, true, Sensors::Continuous}).maxStepsPerTrial(), 200u);
    EXPECT_EQ(HotPlate({2, false, Sensors::Discrete}).maxStepsPerTrial(), 200u);
    EXPECT_EQ(HotPlate({1, false, Sensors::Discrete, 20, 50}).maxStepsPerTrial(), 50u);
}

TEST(HotPlate, BadInputIsRejectedAndChangesNothing) {
    EXPECT_THROW(HotPlate({3, false, Sensors::Discrete}), std::invalid_argument);
    EXPECT_THROW(HotPlate({1, false, Sensors::Discrete, 20, 0}), std::invalid_argument);
    HotPlate plate({1, false, Sensors::Discrete});
    plate.place({5, 0}, 0);
    EXPECT_THROW(plate.act(3), std::invalid_argument);
    EXPECT_THROW(plate.place({20, 0}, 0), std::invalid_argument);
    EXPECT_THROW(plate.place({5, 0}, 1), std::invalid_argument);  // unsignaled: one signal value
    EXPECT_EQ(plate.position(), (Cell{5, 0}));
}
