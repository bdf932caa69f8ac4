// The compact binary save: exact round trips (agents, and brains to brains and agents), and every
// truncation, bit flip and hostile count in an agent's or a brain's save refused with a clear error
// (the same guarantees as the XML save).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <new>

#include "io/snapshot_binary.hpp"
#include "io_test_support.hpp"
#include "verve/io.hpp"

// Records the largest single allocation, so a test can show that a hostile count allocates nothing
// big. Replacing the global operator new is per program: this binary only.
namespace {
std::atomic<std::size_t> g_largestAllocation{0};
}  // namespace

// None of these is inlined: GCC would otherwise match the malloc/free inside them against the
// `new`/`delete` expressions around them and warn (-Wmismatched-new-delete).
__attribute__((noinline)) void* operator new(std::size_t size) {
    std::size_t seen = g_largestAllocation.load(std::memory_order_relaxed);
    while (size > seen && !g_largestAllocation.compare_exchange_weak(seen, size, std::memory_order_relaxed)) {
    }
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
__attribute__((noinline)) void operator delete(void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace verve {
namespace {

using iotest::expectSameFuture;
using iotest::expectSameSnapshot;
using iotest::trainedAgent;
using iotest::trainedBrain;

const SaveOptions kBinary{true, SaveFormat::Binary};

std::string binarySave(const Agent& agent) { return saveAgentToString(agent, kBinary); }


// What the corruption tests damage: an agent's save loaded as an agent, or a brain's as a brain.
enum class Subject { Agent, Brain };

std::string cleanSave(Subject subject) {
    const AgentDescriptor d = iotest::mixedDescriptor();
    return subject == Subject::Agent ? binarySave(trainedAgent(d, 410)) : saveBrainToString(trainedBrain(d, 410), SaveFormat::Binary);
}

std::size_t rbfCountOf(Subject subject, const std::string& bytes) {
    return subject == Subject::Agent ? loadAgentFromMemory(bytes.data(), bytes.size()).rbfCount()
                                     : loadBrainFromMemory(bytes.data(), bytes.size()).rbfCount();
}

void load(Subject subject, const std::string& data) {
    if (subject == Subject::Agent) loadAgentFromMemory(data.data(), data.size());
    else loadBrainFromMemory(data.data(), data.size());
}

// Loading must throw a Format error (or Version, when `versionToo`) with a message.
void expectRefused(const std::string& data, const std::string& what, bool versionToo = false, Subject subject = Subject::Agent) {
    try {
        load(subject, data);
        ADD_FAILURE() << what << " loaded";
    } catch (const Error& e) {
        if (!(versionToo && e.code() == ErrorCode::Version)) {
            EXPECT_EQ(e.code(), ErrorCode::Format) << what << ": " << e.what();
        }
        EXPECT_GT(std::string(e.what()).size(), 20u) << what;
    }
}

TEST(BinarySave, RoundTripIsExactForEveryKindOfAgent) {
    AgentDescriptor discreteOnly;
    discreteOnly.addDiscreteSensor(20).addDiscreteSensor(2);
    discreteOnly.numActions = 5;
    discreteOnly.seed = 0xFFFFFFFFFFFFFFFFULL;
    AgentDescriptor bandit;  // no sensors: one state
    bandit.numActions = 10;
    for (const AgentDescriptor& d : {iotest::mixedDescriptor(), discreteOnly, bandit, iotest::plannerDescriptor(),
                                     iotest::groupedDescriptor(), iotest::customGroupsDescriptor(),
                                     iotest::branchedDescriptor()}) {
        Agent agent = trainedAgent(d, 410);  // 410: stops mid-trial, with traces and a previous step
        const std::string bytes = binarySave(agent);
        Agent loaded = loadAgentFromMemory(bytes.data(), bytes.size());
        expectSameSnapshot(agent.snapshot(), loaded.snapshot());
        EXPECT_EQ(binarySave(loaded), bytes);  // the same bytes when saved again
        // Binary and XML hold the same agent.
        const std::string xml = saveAgentToString(agent);
        expectSameSnapshot(loadAgentFromMemory(xml.data(), xml.size()).snapshot(), loaded.snapshot());
        expectSameFuture(agent, loaded);
    }
}

TEST(BinarySave, IsSmallerThanXmlAndStartsWithItsMagic) {
    Agent agent = trainedAgent(iotest::mixedDescriptor(), 410);
    const std::string bytes = binarySave(agent);
    EXPECT_EQ(bytes.compare(0, 8, "VERVEBIN"), 0);
    EXPECT_LT(bytes.size() * 2, saveAgentToString(agent).size());
}

TEST(BinarySave, WithoutTracesTheLoadedAgentStartsAFreshTrial) {
    Agent agent = trainedAgent(iotest::mixedDescriptor(), 410);
    const std::string bytes = saveAgentToString(agent, SaveOptions{false, SaveFormat::Binary});
    Agent loaded = loadAgentFromMemory(bytes.data(), bytes.size());
    EXPECT_FALSE(loaded.snapshot().hasPrevious);
    EXPECT_TRUE(loaded.snapshot().traceFeatures.empty());
    agent.resetShortTermMemory();
    expectSameFuture(agent, loaded);
}

TEST(BinarySave, ThroughAFileLoadRecognisesTheFormat) {
    const auto path = std::filesystem::temp_directory_path() / "verve_binary_save_test.bin";
    Agent agent = trainedAgent(iotest::mixedDescriptor(11));
    agent.setLearning(false);
    saveAgent(agent, path.string(), kBinary);
    Agent loaded = loadAgent(path.string());
    std::filesystem::remove(path);
    EXPECT_FALSE(loaded.learning());
    expectSameSnapshot(agent.snapshot(), loaded.snapshot());
}

// A brain's binary save holds what an agent's does without the short-term memory, so every route
// between them is exact: brain to brain, brain to agent, agent (a body) to brain.
TEST(BinarySave, BrainSavesLoadAsBrainsAndAsAgentsExactly) {
    for (const AgentDescriptor& d : {iotest::mixedDescriptor(), iotest::plannerDescriptor()}) {
        Brain brain = trainedBrain(d, 410);
        const std::string bytes = saveBrainToString(brain, SaveFormat::Binary);
        ASSERT_EQ(bytes.compare(0, 8, "VERVEBIN"), 0);
        EXPECT_LT(bytes.size() * 2, saveBrainToString(brain).size());

        const Brain copy = loadBrainFromMemory(bytes.data(), bytes.size());
        expectSameSnapshot(brain.snapshot(), copy.snapshot());
        EXPECT_EQ(saveBrainToString(copy, SaveFormat::Binary), bytes);
        const std::string xml = saveBrainToString(brain);  // both formats hold the same brain
        expectSameSnapshot(loadBrainFromMemory(xml.data(), xml.size()).snapshot(), copy.snapshot());

        // As an agent: the brain's weights with a fresh short-term memory, learning on from there
        // exactly as an agent made from the brain in memory.
        Agent agent = loadAgentFromMemory(bytes.data(), bytes.size());
        expectSameSnapshot(brain.snapshot(), agent.snapshot());
        Agent inMemory(brain.snapshot());
        expectSameFuture(inMemory, agent);

        // A body's (an agent's) save as a brain: the body's short-term memory is left out.
        Agent body = brain.makeBody();
        iotest::Feed feed(5);
        iotest::drive(body, feed, 30);
        const std::string bodyBytes = binarySave(body);
        const Brain fromBody = loadBrainFromMemory(bodyBytes.data(), bodyBytes.size());
        expectSameSnapshot(brain.snapshot(), fromBody.snapshot());
        EXPECT_EQ(saveBrainToString(fromBody, SaveFormat::Binary), saveBrainToString(brain, SaveFormat::Binary));
    }
}

// What a save from before version 5 reads: no adaptation (it learns on as it did), nothing measured.
void asBeforeAdaptation(AgentSnapshot& snap) {
    snap.descriptor.adaptation = 0;
    snap.horizonTrialSeconds = snap.tdMeanSquare = snap.trialSeconds = 0.0f;
    snap.horizonTrials = 0;
}

// What a save from before version 8 reads: the whole trial one stretch of an unchanged reward.
void asBeforeStretches(AgentSnapshot& snap) {
    snap.stretchSeconds = snap.trialSeconds;
    snap.stretchLongest = snap.stretchReward = 0.0f;
    snap.stretchSeen = false;
}

// Version 1 (before the reward range) is version 2 without the range's 8 bytes after the weights.
// Such a save loads with the widest range, [-1, 1], the value bound version 1 used.
// The save of `snap` as an older binary format version wrote it: the fields that version did not
// have (after the weights: the reward range from version 2, the model flag from version 3, the final
// reward range from version 4, the adaptations' fields from version 5) removed.
std::string asVersion(std::string bytes, const AgentSnapshot& snap, std::uint32_t version) {
    char tail[21];
    std::memcpy(tail, &snap.weights.back(), 4);
    std::memcpy(tail + 4, &snap.rewardLow, 4);
    std::memcpy(tail + 8, &snap.rewardHigh, 4);
    tail[12] = snap.modelPredictsChange ? 1 : 0;
    std::memcpy(tail + 13, &snap.finalRewardLow, 4);
    std::memcpy(tail + 17, &snap.finalRewardHigh, 4);
    const std::size_t at = bytes.find(std::string(tail, 21), io::kBinaryHeaderBytes);
    if (at == std::string::npos) return {};
    // After the final reward range: version 5's 16 bytes, version 6's 9 (the grouping and a list
    // of groups, empty for these agents), version 7's 8 (an empty list of action branches),
    // version 8's 4 (no continuous actions), version 9's group rates (three lists), then the
    // short-term memory flag and, from version 5, the trial's seconds.
    // With short-term memory, version 8's 13 bytes of reward stretches follow the trial's seconds.
    bytes.erase(at + 58, 24 + 4 * (snap.groupLogRates.size() + snap.groupNorms.size() + snap.groupHistory.size()));
    const bool shortTerm = bytes[at + 58] == 1;
    if (shortTerm) bytes.erase(at + 63, 13);
    if (version < 5 && shortTerm) bytes.erase(at + 59, 4);
    bytes.erase(at + 54, 4);
    if (version < 7) bytes.erase(at + 46, 8);
    if (version < 6) bytes.erase(at + 37, 9);
    if (version < 5) bytes.erase(at + 21, 16);
    if (version == 1) bytes.erase(at + 4, 17);
    if (version == 2) bytes.erase(at + 12, 9);
    if (version == 3) bytes.erase(at + 13, 8);
    const std::uint64_t payload = bytes.size() - io::kBinaryHeaderBytes;
    const std::uint64_t sum = io::payloadChecksum(bytes.data() + io::kBinaryHeaderBytes, payload);
    std::memcpy(&bytes[8], &version, 4);
    std::memcpy(&bytes[16], &payload, 8);
    std::memcpy(&bytes[24], &sum, 8);
    return bytes;
}

// Saves from before adaptation were made with one lattice over the sensors: an agent as then.
AgentDescriptor beforeFineLattices(AgentDescriptor d) {
    d.adaptation &= ~verve::Adaptation::FineLattice;
    return d;
}

TEST(BinarySave, Version1SavesLoadWithTheWidestRewardRange) {
    Agent agent = trainedAgent(beforeFineLattices(iotest::plannerDescriptor()), 410);
    AgentSnapshot snap = agent.snapshot();
    ASSERT_LT(snap.rewardLow, 0.0f);  // a range narrower than [-1, 1], so the test can tell
    ASSERT_LT(snap.rewardHigh, 1.0f);
    ASSERT_TRUE(snap.modelPredictsChange);
    const std::string bytes = asVersion(binarySave(agent), snap, 1);
    ASSERT_FALSE(bytes.empty());

    const AgentSnapshot loaded = loadAgentFromMemory(bytes.data(), bytes.size()).snapshot();
    EXPECT_EQ(loaded.rewardLow, -1.0f);
    EXPECT_EQ(loaded.rewardHigh, 1.0f);
    EXPECT_FALSE(loaded.modelPredictsChange);
    snap.rewardLow = -1.0f;
    snap.rewardHigh = 1.0f;
    snap.modelPredictsChange = false;
    snap.finalRewardLow = snap.finalRewardHigh = 0.0f;
    asBeforeAdaptation(snap);
    asBeforeStretches(snap);
    expectSameSnapshot(snap, loaded);
}

// A save from before final rewards were counted apart reads [0, 0] for them: its reward range holds
// every reward it learned from, so its value bounds stay as wide as they were.
TEST(BinarySave, Version5SavesOfManySensorsKeepTheirOneLattice) {
    // Before sensor groups, an agent of 6 continuous sensors had one lattice over all of them:
    // it must load so, not with what Auto now chooses for 6 sensors.
    AgentDescriptor d = iotest::groupedDescriptor();
    d.grouping = SensorGrouping::Joint;
    d.maxRbfs = 100000;
    Agent agent = trainedAgent(d, 410);
    AgentSnapshot snap = agent.snapshot();
    const std::string bytes = asVersion(binarySave(agent), snap, 5);
    ASSERT_FALSE(bytes.empty());
    const AgentSnapshot loaded = loadAgentFromMemory(bytes.data(), bytes.size()).snapshot();
    EXPECT_EQ(loaded.descriptor.grouping, SensorGrouping::Joint);
    asBeforeStretches(snap);
    expectSameSnapshot(snap, loaded);
}

TEST(BinarySave, Version6SavesHaveOneActionSet) {
    Agent agent = trainedAgent(iotest::mixedDescriptor(), 410);
    AgentSnapshot snap = agent.snapshot();
    const std::string bytes = asVersion(binarySave(agent), snap, 6);
    ASSERT_FALSE(bytes.empty());
    const AgentSnapshot loaded = loadAgentFromMemory(bytes.data(), bytes.size()).snapshot();
    EXPECT_TRUE(loaded.descriptor.actionBranches.empty());
    asBeforeStretches(snap);
    expectSameSnapshot(snap, loaded);
}

TEST(BinarySave, Version3SavesReadNoFinalRewardRange) {
    Agent agent = trainedAgent(beforeFineLattices(iotest::plannerDescriptor()), 410);
    AgentSnapshot snap = agent.snapshot();
    ASSERT_LT(snap.finalRewardLow, 0.0f);  // the test's trials end with rewards of both signs
    ASSERT_GT(snap.finalRewardHigh, 0.0f);
    const std::string bytes = asVersion(binarySave(agent), snap, 3);
    ASSERT_FALSE(bytes.empty());
    const AgentSnapshot loaded = loadAgentFromMemory(bytes.data(), bytes.size()).snapshot();
    snap.finalRewardLow = snap.finalRewardHigh = 0.0f;
    asBeforeAdaptation(snap);
    asBeforeStretches(snap);
    expectSameSnapshot(snap, loaded);
}

// A save from before the model predicted changes keeps its model's meaning: positions.
TEST(BinarySave, Version2SavesKeepAModelThatPredictsPositions) {
    Agent agent = trainedAgent(beforeFineLattices(iotest::plannerDescriptor()), 410);
    AgentSnapshot snap = agent.snapshot();
    const std::string bytes = asVersion(binarySave(agent), snap, 2);
    ASSERT_FALSE(bytes.empty());
    Agent loaded = loadAgentFromMemory(bytes.data(), bytes.size());
    snap.modelPredictsChange = false;
    snap.finalRewardLow = snap.finalRewardHigh = 0.0f;
    asBeforeAdaptation(snap);
    asBeforeStretches(snap);
    expectSameSnapshot(snap, loaded.snapshot());
    // It learns on as it did, and its next save says so.
    iotest::Feed feed(5);
    iotest::drive(loaded, feed, 50);
    const std::string again = binarySave(loaded);
    EXPECT_FALSE(loadAgentFromMemory(again.data(), again.size()).snapshot().modelPredictsChange);
}

TEST(BinarySave, BrainFilesLoadAsBrainsAndAsAgents) {
    const auto path = std::filesystem::temp_directory_path() / "verve_binary_brain_test.bin";
    const Brain brain = trainedBrain(iotest::mixedDescriptor(13));
    saveBrain(brain, path.string(), SaveFormat::Binary);
    const Brain loaded = loadBrain(path.string());
    const Agent agent = loadAgent(path.string());
    std::filesystem::remove(path);
    expectSameSnapshot(brain.snapshot(), loaded.snapshot());
    expectSameSnapshot(brain.snapshot(), agent.snapshot());
}

class CorruptBinarySave : public ::testing::TestWithParam<Subject> {
protected:
    void SetUp() override { bytes_ = cleanSave(GetParam()); }
    void expectRefused(const std::string& data, const std::string& what, bool versionToo = false) const {
        verve::expectRefused(data, what, versionToo, GetParam());
    }

    // The save with the u64 at payload offset `at` replaced and the checksum made valid again:
    // what a hostile writer (not random damage) can produce.
    std::string withCount(std::size_t at, std::uint64_t value) const {
        std::string s = bytes_;
        std::memcpy(&s[io::kBinaryHeaderBytes + at], &value, 8);
        const std::uint64_t sum = io::payloadChecksum(s.data() + io::kBinaryHeaderBytes, s.size() - io::kBinaryHeaderBytes);
        std::memcpy(&s[24], &sum, 8);
        return s;
    }
    std::uint64_t countAt(std::size_t at) const {
        std::uint64_t v = 0;
        std::memcpy(&v, bytes_.data() + io::kBinaryHeaderBytes + at, 8);
        return v;
    }

    std::string bytes_;
};

TEST_P(CorruptBinarySave, EveryTruncationIsRefused) {
    for (std::size_t cut = 1; cut < bytes_.size(); ++cut) {
        expectRefused(bytes_.substr(0, cut), "a save cut at byte " + std::to_string(cut));
    }
    expectRefused(bytes_ + "x", "a save with a byte appended");
}

TEST_P(CorruptBinarySave, EverySingleBitFlipIsRefused) {
    for (std::size_t bit = 0; bit < bytes_.size() * 8; ++bit) {
        std::string s = bytes_;
        s[bit / 8] = static_cast<char>(s[bit / 8] ^ (1 << (bit % 8)));
        // A flip in the version field may read as a newer version: a Version error.
        const bool inVersion = bit / 8 >= 8 && bit / 8 < 12;
        expectRefused(s, "a flip of bit " + std::to_string(bit), inVersion);
    }
}

TEST_P(CorruptBinarySave, FutureVersionIsAVersionError) {
    std::string s = bytes_;
    const std::uint32_t newer = io::kBinaryFormatVersion + 1;
    std::memcpy(&s[8], &newer, 4);
    try {
        load(GetParam(), s);
        ADD_FAILURE() << "a newer version loaded";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::Version) << e.what();
        EXPECT_NE(std::string(e.what()).find("version " + std::to_string(newer)), std::string::npos) << e.what();
    }
}

TEST_P(CorruptBinarySave, ChecksumMismatchIsNamed) {
    std::string s = bytes_;
    s.back() = static_cast<char>(s.back() ^ 0x10);
    try {
        load(GetParam(), s);
        ADD_FAILURE();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
    }
}

// The payload of the mixed agent (1 discrete, 2 continuous sensors): the descriptor's fixed part
// is 66 bytes, then the discrete sensors' count and values, the continuous sensors' count and
// flags, then the state's 49 bytes, then the feature keys' count.
constexpr std::size_t kDiscreteCountAt = 66;
constexpr std::size_t kFeatureCountAt = 66 + 8 + 4 + 8 + 2 + 49;

TEST_P(CorruptBinarySave, HugeCountsAreRefusedWithoutAllocating) {
    ASSERT_EQ(countAt(kDiscreteCountAt), 1u);  // the layout this test edits
    ASSERT_EQ(countAt(kFeatureCountAt), rbfCountOf(GetParam(), bytes_));
    for (std::size_t at : {kDiscreteCountAt, kFeatureCountAt}) {
        for (std::uint64_t count : {std::uint64_t{1} << 28, std::uint64_t{1} << 61, ~std::uint64_t{0}}) {
            const std::string hostile = withCount(at, count);
            g_largestAllocation = 0;
            try {
                load(GetParam(), hostile);
                ADD_FAILURE() << "a count of " << count << " loaded";
            } catch (const Error& e) {
                EXPECT_EQ(e.code(), ErrorCode::Format);
                EXPECT_NE(std::string(e.what()).find("declares"), std::string::npos) << e.what();
            }
            EXPECT_LT(g_largestAllocation.load(), bytes_.size() + 4096) << "count " << count;
        }
    }
}

TEST_P(CorruptBinarySave, AConsistentButWrongSaveGetsTheSameChecksAsXml) {
    // One feature key fewer, checksum valid: the snapshot checks catch what the layout cannot.
    const std::string s = withCount(kFeatureCountAt, countAt(kFeatureCountAt) - 1);
    expectRefused(s, "a save whose lists disagree");
}

INSTANTIATE_TEST_SUITE_P(AgentAndBrain, CorruptBinarySave, ::testing::Values(Subject::Agent, Subject::Brain),
                         [](const ::testing::TestParamInfo<Subject>& param) {
                             return param.param == Subject::Agent ? "AgentSave" : "BrainSave";
                         });

}  // namespace
}  // namespace verve
