// Demonstrated and praised continuous actions (docs/teaching.md): the teacher's values are checked
// (a refused call changes nothing), played back, learned from deterministically, kept in recordings
// (both format versions load), and praise moves a continuous action's mean towards praised values.
// In the io tests: it saves agents and reads recordings' bytes, which the core tests do not link.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "io/snapshot_binary.hpp"
#include "verve/agent.hpp"
#include "verve/error.hpp"
#include "verve/io.hpp"
#include "verve/recording.hpp"

using namespace verve;

namespace {

AgentDescriptor steering(std::uint32_t continuous, std::uint64_t seed = 1) {
    AgentDescriptor d;
    d.addContinuousSensor();
    d.numActions = 1;
    d.continuousActions = continuous;
    d.seed = seed;
    return d;
}

Observation at(const AgentDescriptor& d, float x) {
    Observation obs(d);
    obs.setContinuous(0, x);
    return obs;
}

std::string bytesOf(const Agent& agent) { return saveAgentToString(agent, SaveOptions{true, SaveFormat::Binary}); }

float greedyAt(Agent& agent, float x) {
    agent.setActionSelection(ActionSelection::Greedy);
    agent.setLearning(false);
    agent.update(0.0f, at(agent.descriptor(), x), 0.05f);
    const float value = agent.continuousAction()[0];
    agent.setLearning(true);
    agent.setActionSelection(ActionSelection::Sample);
    return value;
}

}  // namespace

TEST(ContinuousDemonstration, RefusedValuesChangeNothing) {
    const AgentDescriptor d = steering(2);
    Agent agent(d);
    agent.update(0.0f, at(d, 0.2f), 0.05f);
    const std::string before = bytesOf(agent);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<std::vector<float>> bad = {{0.5f}, {0.5f, 0.5f, 0.5f}, {nan, 0.0f}, {0.0f, 1.01f}, {-1.5f, 0.0f},
                                                 {std::numeric_limits<float>::infinity(), 0.0f}};
    for (const auto& values : bad) {
        try {
            agent.updateDemonstrated(0.1f, at(d, 0.3f).view(), 0.05f, 0, ContinuousActionView{values.data(), std::uint32_t(values.size())});
            ADD_FAILURE() << "accepted " << values.size() << " values";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
            EXPECT_NE(std::string(e.what()).find("demonstrated continuous action"), std::string::npos) << e.what();
        }
        EXPECT_EQ(bytesOf(agent), before);
    }
    EXPECT_THROW(agent.updateDemonstrated(0.1f, at(d, 0.3f).view(), 0.05f, 0, ContinuousActionView{nullptr, 2}), Error);
    EXPECT_EQ(bytesOf(agent), before);
}

TEST(ContinuousDemonstration, TheTeachersValuesArePlayedIncludingTheBounds) {
    const AgentDescriptor d = steering(2);
    Agent agent(d);
    const float values[] = {1.0f, -1.0f};
    for (int i = 0; i < 50; ++i) {
        agent.updateDemonstrated(-0.1f, at(d, 0.1f * float(i % 10)).view(), 0.05f, 0, ContinuousActionView{values, 2});
        EXPECT_EQ(agent.continuousAction(), std::vector<float>(values, values + 2));
    }
    agent.endEpisode(-1.0f);
    // At the squash's edges the gradients stay clipped: every value the agent then plays is finite.
    for (int i = 0; i < 20; ++i) {
        agent.update(0.0f, at(d, 0.05f * float(i)), 0.05f);
        for (float v : agent.continuousAction()) EXPECT_TRUE(std::isfinite(v) && v >= -1.0f && v <= 1.0f);
    }
}

TEST(ContinuousDemonstration, IsDeterministic) {
    const AgentDescriptor d = steering(1, 7);
    Agent a(d), b(d);
    for (Agent* agent : {&a, &b}) {
        for (int i = 0; i < 200; ++i) {
            const float v = std::sin(0.1f * float(i));
            if (i % 3 == 0) agent->update(-0.1f, at(d, v), 0.05f);
            else agent->updateDemonstrated(-0.1f, at(d, v).view(), 0.05f, 0, ContinuousActionView{&v, 1});
        }
    }
    EXPECT_EQ(bytesOf(a), bytesOf(b));
}

TEST(ContinuousDemonstration, DemonstrationsPullTheMeanTowardsTheTeachersValue) {
    const AgentDescriptor d = steering(1);
    Agent agent(d);
    const float before = greedyAt(agent, 0.4f);
    const float teacher = 0.8f;
    for (int i = 0; i < 40; ++i) agent.updateDemonstrated(0.0f, at(d, 0.4f).view(), 0.05f, 0, ContinuousActionView{&teacher, 1});
    const float after = greedyAt(agent, 0.4f);
    EXPECT_GT(after, before + 0.2f) << before << " -> " << after;
    EXPECT_LE(after, 1.0f);
}

TEST(ContinuousDemonstration, WithoutContinuousActionsAnEmptyViewIsAPlainDemonstration) {
    AgentDescriptor d;
    d.addContinuousSensor();
    d.numActions = 3;
    Agent a(d), b(d);
    a.updateDemonstrated(0.0f, at(d, 0.1f).view(), 0.05f, 2);
    b.updateDemonstrated(0.0f, at(d, 0.1f).view(), 0.05f, 2, ContinuousActionView{});
    EXPECT_EQ(bytesOf(a), bytesOf(b));
}

// Each 2.5 s (the memory's window) judged by where its acts pushed on average: praised when
// right, scolded when left. The mean moves right, beside the same agent with no judgements.
TEST(ContinuousDemonstration, PraiseMovesTheMeanTowardsPraisedValues) {
    const AgentDescriptor d = steering(1, 3);
    Agent taught(d), untaught(d);
    taught.teach(0.0f);  // arms the memory; untaught stays unarmed
    float pushed = 0.0f;
    for (int i = 1; i <= 2000; ++i) {
        taught.update(0.0f, at(d, 0.3f), 0.05f);
        untaught.update(0.0f, at(d, 0.3f), 0.05f);
        pushed += taught.continuousAction()[0];
        if (i % 50 == 0) {
            taught.teach(pushed > 0.0f ? 1.0f : -1.0f);
            pushed = 0.0f;
        }
    }
    const float praised = greedyAt(taught, 0.3f), plain = greedyAt(untaught, 0.3f);
    std::printf("[ measured ] greedy at x = 0.3 after 40 judgements: %.3f praised, %.3f not\n", praised, plain);
    EXPECT_GT(praised, plain + 0.1f) << praised << " vs " << plain;
}

namespace {

Recording drive(const AgentDescriptor& d) {
    Recording r = Recording::shapedLike(d);
    for (int i = 0; i < 30; ++i) {
        const float x = 0.05f * float(i) - 0.7f;
        const float steer[2] = {-x, i % 2 ? 1.0f : -0.25f};
        if (i % 5 == 4) r.addStep(-std::fabs(x), at(d, x).view(), 0.05f, 0);
        else r.addStep(-std::fabs(x), at(d, x).view(), 0.05f, 0, ContinuousActionView{steer, 2});
        if (i == 14) r.addTruncation(-0.5f);
    }
    r.addEndEpisode(1.0f);
    return r;
}

}  // namespace

TEST(ContinuousDemonstration, RecordingsKeepTheValuesAndReplayAsLiveCalls) {
    const AgentDescriptor d = steering(2);
    const Recording r = drive(d);
    EXPECT_EQ(r.continuousActions(), 2u);
    EXPECT_EQ(r.continuousActionValues().size(), 2u * 24u);
    const Recording loaded = recordingFromBytes(recordingToBytes(r).data(), recordingToBytes(r).size());
    EXPECT_EQ(loaded.kinds(), r.kinds());
    EXPECT_EQ(loaded.continuousActionValues(), r.continuousActionValues());
    EXPECT_EQ(recordingToBytes(loaded), recordingToBytes(r));
    Agent replayed(d), live(d), fromFile(d);
    r.replayInto(replayed);
    loaded.replayInto(fromFile);
    for (int i = 0; i < 30; ++i) {
        const float x = 0.05f * float(i) - 0.7f;
        const float steer[2] = {-x, i % 2 ? 1.0f : -0.25f};
        if (i % 5 == 4) live.updateDemonstrated(-std::fabs(x), at(d, x).view(), 0.05f, 0);
        else live.updateDemonstrated(-std::fabs(x), at(d, x).view(), 0.05f, 0, ContinuousActionView{steer, 2});
        if (i == 14) live.truncateEpisode(-0.5f);
    }
    live.endEpisode(1.0f);
    EXPECT_EQ(bytesOf(replayed), bytesOf(live));
    EXPECT_EQ(bytesOf(fromFile), bytesOf(live));
    // Steps with continuous values replay only into agents with as many continuous actions.
    Agent other(steering(1));
    EXPECT_THROW(r.replayInto(other), Error);
}

TEST(ContinuousDemonstration, RecordingsRefuseBadValuesAndRecordNothing) {
    const AgentDescriptor d = steering(2);
    Recording r = Recording::shapedLike(d);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float one[1] = {0.0f}, bad[2] = {0.0f, nan}, far[2] = {2.0f, 0.0f};
    EXPECT_THROW(r.addStep(0.0f, at(d, 0.0f).view(), 0.05f, 0, ContinuousActionView{one, 1}), Error);
    EXPECT_THROW(r.addStep(0.0f, at(d, 0.0f).view(), 0.05f, 0, ContinuousActionView{bad, 2}), Error);
    EXPECT_THROW(r.addStep(0.0f, at(d, 0.0f).view(), 0.05f, 0, ContinuousActionView{far, 2}), Error);
    EXPECT_THROW(r.addStep(0.0f, at(d, 0.0f).view(), 0.05f, 0, ContinuousActionView{nullptr, 2}), Error);
    EXPECT_EQ(r.size(), 0u);
    EXPECT_TRUE(r.continuousActionValues().empty());
}

namespace {

template <typename T>
void put(std::string& out, const T& v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

}  // namespace

// A version 1 file (before continuous actions were recorded), written field by field as that
// format had it: it loads, and replays as before.
TEST(ContinuousDemonstration, VersionOneRecordingsStillLoad) {
    std::string payload;
    put(payload, std::uint32_t{3});  // actions
    put(payload, std::uint32_t{0});  // discrete sensors
    put(payload, std::uint32_t{1});  // continuous sensors
    put(payload, std::uint64_t{3});  // entries
    put(payload, std::uint64_t{2});  // steps
    for (std::uint8_t kind : {std::uint8_t{0}, std::uint8_t{0}, std::uint8_t{1}}) put(payload, kind);
    for (float reward : {0.0f, -0.5f, 1.0f}) put(payload, reward);
    for (float dt : {0.05f, 0.05f}) put(payload, dt);
    for (std::uint32_t action : {2u, 1u}) put(payload, action);
    for (float x : {0.25f, -0.5f}) put(payload, x);
    std::string file("VERVEREC", 8);
    put(file, std::uint32_t{1});
    put(file, std::uint32_t{0});
    put(file, std::uint64_t{payload.size()});
    put(file, io::payloadChecksum(payload.data(), payload.size()));
    file += payload;
    const Recording r = recordingFromBytes(file.data(), file.size());
    EXPECT_EQ(r.size(), 3u);
    EXPECT_EQ(r.steps(), 2u);
    EXPECT_EQ(r.continuousActions(), 0u);
    EXPECT_EQ(r.actions(), (std::vector<std::uint32_t>{2, 1}));
    AgentDescriptor d;
    d.addContinuousSensor();
    d.numActions = 3;
    Agent agent(d);
    r.replayInto(agent);
    EXPECT_EQ(agent.stats().steps, 2u);
}

// The fuzz corpus's steering recording as version 1 wrote it (3 continuous sensors, 2 actions, 8 steps,
// a truncation and an end): it loads and replays into the steering agent it was made for.
TEST(ContinuousDemonstration, AVersionOneFileStillLoads) {
    const Recording r = loadRecording(std::string(VERVE_IO_TEST_DATA) + "/recording_v1_steering.vrec");
    EXPECT_EQ(r.size(), 10u);
    EXPECT_EQ(r.steps(), 8u);
    EXPECT_EQ(r.continuousSensors(), 3u);
    EXPECT_EQ(r.continuousActions(), 0u);
    EXPECT_TRUE(r.continuousActionValues().empty());
    AgentDescriptor d;
    for (int i = 0; i < 3; ++i) d.addContinuousSensor();
    d.numActions = 2;
    d.continuousActions = 2;
    Agent agent(d);
    r.replayInto(agent);
    EXPECT_EQ(agent.stats().steps, 8u);
    // Saved again, it is a version 2 file that loads to the same entries.
    const std::string bytes = recordingToBytes(r);
    std::uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 8, 4);
    EXPECT_EQ(version, 2u);
    EXPECT_EQ(recordingFromBytes(bytes.data(), bytes.size()).kinds(), r.kinds());
}
