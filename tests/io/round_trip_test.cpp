// Save then load gives the same agent: every field bit for bit, and the same future actions.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <string>

#include <pugixml.hpp>

#include "io_test_support.hpp"
#include "xml_edit.hpp"
#include "verve/io.hpp"

namespace verve {
namespace {

using iotest::expectSameFuture;
using iotest::expectSameSnapshot;
using iotest::trainedAgent;

// The XML save with these attributes of <state> removed: how a save from before them reads.
std::string withoutStateAttributes(const std::string& xml, std::initializer_list<const char*> names) {
    return iotest::editedXml(xml, [&](pugi::xml_node root) {
        pugi::xml_node state = root.child("state");
        for (const char* name : names) EXPECT_TRUE(state.remove_attribute(name)) << name;
    });
}

TEST(RoundTrip, MixedSensorsMidTrialFromMemory) {
    Agent agent = trainedAgent(iotest::mixedDescriptor(), 410);  // 410: stops mid-trial
    ASSERT_GT(agent.rbfCount(), 10u);
    ASSERT_TRUE(agent.snapshot().hasPrevious);
    ASSERT_FALSE(agent.snapshot().traceFeatures.empty());
    const std::string xml = saveAgentToString(agent);
    Agent loaded = loadAgentFromMemory(xml.data(), xml.size());
    expectSameSnapshot(agent.snapshot(), loaded.snapshot());
    EXPECT_EQ(saveAgentToString(loaded), xml);  // saving is deterministic
    expectSameFuture(agent, loaded);
}

TEST(RoundTrip, SensorGroupsKeepTheirLatticesAndAreSavedAsTheyWereMade) {
    for (const AgentDescriptor& d : {iotest::groupedDescriptor(), iotest::customGroupsDescriptor()}) {
        Agent agent = trainedAgent(d, 410);
        const std::string xml = saveAgentToString(agent);
        // Older libraries refuse it: version 2 for the groups, 5 for their rates (the default).
        const bool rates = (d.adaptation & verve::Adaptation::GroupRates) != 0;
        EXPECT_NE(xml.find(rates ? "format_version=\"5\"" : "format_version=\"2\""), std::string::npos);
        EXPECT_EQ(xml.find("<group_rates>") != std::string::npos, rates);
        EXPECT_NE(xml.find("grouping=\"custom\""), std::string::npos);   // Auto's choice, written out
        Agent loaded = loadAgentFromMemory(xml.data(), xml.size());
        expectSameSnapshot(agent.snapshot(), loaded.snapshot());
        EXPECT_EQ(saveAgentToString(loaded), xml);
        expectSameFuture(agent, loaded);
    }
    // An agent of a few sensors and one action set writes nothing new: older libraries still read its saves.
    const std::string plain = saveAgentToString(trainedAgent(iotest::mixedDescriptor(), 50));
    EXPECT_NE(plain.find("format_version=\"1\""), std::string::npos);
    EXPECT_EQ(plain.find("grouping"), std::string::npos);
    EXPECT_EQ(plain.find("action_branch"), std::string::npos);
}

TEST(RoundTrip, ActionBranchesAndTheirTracesSurvive) {
    Agent agent = trainedAgent(iotest::branchedDescriptor(), 410);
    const std::string xml = saveAgentToString(agent);
    EXPECT_NE(xml.find("format_version=\"3\""), std::string::npos);  // older libraries refuse it
    EXPECT_NE(xml.find("<action_branch choices=\"3\""), std::string::npos);
    Agent loaded = loadAgentFromMemory(xml.data(), xml.size());
    EXPECT_EQ(loaded.descriptor().actionBranches, (std::vector<std::uint32_t>{3, 2, 2}));
    EXPECT_EQ(loaded.descriptor().numActions, 12u);
    expectSameSnapshot(agent.snapshot(), loaded.snapshot());
    EXPECT_EQ(saveAgentToString(loaded), xml);
    expectSameFuture(agent, loaded);
}

TEST(RoundTrip, ThroughAFile) {
    const auto path = std::filesystem::temp_directory_path() / "verve_round_trip_test.xml";
    Agent agent = trainedAgent(iotest::mixedDescriptor(11));
    saveAgent(agent, path.string());
    Agent loaded = loadAgent(path.string());
    std::filesystem::remove(path);
    expectSameFuture(agent, loaded);
}

TEST(RoundTrip, WithoutTracesTheLoadedAgentStartsAFreshTrial) {
    Agent agent = trainedAgent(iotest::mixedDescriptor(), 410);
    const std::string xml = saveAgentToString(agent, SaveOptions{false});
    EXPECT_EQ(xml.find("<traces"), std::string::npos);
    EXPECT_EQ(xml.find("<previous"), std::string::npos);
    Agent loaded = loadAgentFromMemory(xml.data(), xml.size());
    const AgentSnapshot s = loaded.snapshot();
    expectSameSnapshot(agent.snapshot(), s, /*withTraces=*/false);
    EXPECT_TRUE(s.traceFeatures.empty());
    EXPECT_FALSE(s.hasPrevious);
    // Same as the original after it forgets its short-term memory.
    agent.resetShortTermMemory();
    expectSameFuture(agent, loaded);
}

TEST(RoundTrip, DescriptorVariants) {
    AgentDescriptor discreteOnly;
    discreteOnly.addDiscreteSensor(20).addDiscreteSensor(2);
    discreteOnly.numActions = 5;
    discreteOnly.policyMultiplier = 10.0f;
    discreteOnly.seed = 0xFFFFFFFFFFFFFFFFULL;

    AgentDescriptor bandit;  // no sensors at all: one state
    bandit.numActions = 10;
    bandit.tauValue = 0.0f;

    const AgentDescriptor full = iotest::plannerDescriptor();

    for (const AgentDescriptor& d : {discreteOnly, bandit, full}) {
        Agent agent = trainedAgent(d, 120);
        const std::string xml = saveAgentToString(agent);
        Agent loaded = loadAgentFromMemory(xml.data(), xml.size());
        expectSameSnapshot(agent.snapshot(), loaded.snapshot());
        expectSameFuture(agent, loaded);
    }
}

TEST(RoundTrip, PolicyWeightBoundIsKeptAndOnlyWrittenWhenSet) {
    AgentDescriptor d = iotest::mixedDescriptor();
    const std::string unbounded = saveAgentToString(trainedAgent(d, 50));
    EXPECT_EQ(unbounded.find("policy_weight_bound"), std::string::npos);  // older libraries read it
    EXPECT_EQ(loadAgentFromMemory(unbounded.data(), unbounded.size()).descriptor().policyWeightBound, 0.0f);
    d.policyWeightBound = 3.5f;
    Agent agent = trainedAgent(d, 120);
    const std::string xml = saveAgentToString(agent);
    Agent loaded = loadAgentFromMemory(xml.data(), xml.size());
    EXPECT_EQ(loaded.descriptor().policyWeightBound, 3.5f);
    expectSameSnapshot(agent.snapshot(), loaded.snapshot());
    expectSameFuture(agent, loaded);
}

// The range of real rewards bounds the values TD errors bootstrap from: it is saved, and a save
// from before it loads with the widest range, [-1, 1], the bound those versions used.
TEST(RoundTrip, RewardRangeIsKeptAndOldSavesGetTheWidest) {
    Agent agent = trainedAgent(iotest::plannerDescriptor(), 120);
    const std::string xml = saveAgentToString(agent);
    const AgentSnapshot loaded = loadAgentFromMemory(xml.data(), xml.size()).snapshot();
    EXPECT_EQ(loaded.rewardLow, agent.snapshot().rewardLow);
    EXPECT_EQ(loaded.rewardHigh, agent.snapshot().rewardHigh);
    EXPECT_LT(loaded.rewardLow, 0.0f);

    const std::string old = withoutStateAttributes(xml, {"reward_low", "reward_high"});
    const AgentSnapshot widest = loadAgentFromMemory(old.data(), old.size()).snapshot();
    EXPECT_EQ(widest.rewardLow, -1.0f);
    EXPECT_EQ(widest.rewardHigh, 1.0f);
}

// The final rewards (those that ended a trial) are saved apart; a save from before that reads [0, 0]
// for them, and its reward range, which holds every reward, keeps its bounds as wide as they were.
TEST(RoundTrip, FinalRewardRangeIsKeptAndOldSavesReadNone) {
    Agent agent = trainedAgent(iotest::plannerDescriptor(), 120);
    const AgentSnapshot snap = agent.snapshot();
    ASSERT_LT(snap.finalRewardLow, 0.0f);
    ASSERT_GT(snap.finalRewardHigh, 0.0f);
    const std::string xml = saveAgentToString(agent);
    const AgentSnapshot loaded = loadAgentFromMemory(xml.data(), xml.size()).snapshot();
    EXPECT_EQ(loaded.finalRewardLow, snap.finalRewardLow);
    EXPECT_EQ(loaded.finalRewardHigh, snap.finalRewardHigh);

    const std::string old = withoutStateAttributes(xml, {"final_reward_low", "final_reward_high"});
    const AgentSnapshot none = loadAgentFromMemory(old.data(), old.size()).snapshot();
    EXPECT_EQ(none.finalRewardLow, 0.0f);
    EXPECT_EQ(none.finalRewardHigh, 0.0f);
    EXPECT_EQ(none.rewardLow, snap.rewardLow);
}

// New agents' models predict how far continuous sensors move; a save from before that keeps a
// model of where they land, and says so when saved again.
TEST(RoundTrip, TheModelsMeaningIsKeptAndOldSavesPredictPositions) {
    Agent agent = trainedAgent(iotest::plannerDescriptor(), 120);
    const std::string xml = saveAgentToString(agent);
    EXPECT_NE(xml.find("continuous_model=\"change\""), std::string::npos);
    EXPECT_TRUE(loadAgentFromMemory(xml.data(), xml.size()).snapshot().modelPredictsChange);

    const std::string old = withoutStateAttributes(xml, {"continuous_model"});
    Agent loaded = loadAgentFromMemory(old.data(), old.size());
    EXPECT_FALSE(loaded.snapshot().modelPredictsChange);
    iotest::Feed feed(5);
    iotest::drive(loaded, feed, 50);
    EXPECT_NE(saveAgentToString(loaded).find("continuous_model=\"position\""), std::string::npos);
}

TEST(RoundTrip, LearningSwitchIsKept) {
    Agent agent = trainedAgent(iotest::mixedDescriptor(), 100);
    agent.setLearning(false);
    const std::string xml = saveAgentToString(agent);
    EXPECT_FALSE(loadAgentFromMemory(xml.data(), xml.size()).learning());
}

TEST(RoundTrip, TheFormatIsReadableXml) {
    Agent agent = trainedAgent(iotest::mixedDescriptor(), 50);
    const std::string xml = saveAgentToString(agent);
    EXPECT_EQ(xml.rfind("<?xml", 0), 0u);
    EXPECT_NE(xml.find("<verve_agent format_version=\"1\""), std::string::npos);
    EXPECT_NE(xml.find("<continuous_sensor circular=\"true\""), std::string::npos);
    EXPECT_NE(xml.find("tau_value=\"0.1\""), std::string::npos);  // shortest exact form
}

}  // namespace
}  // namespace verve
