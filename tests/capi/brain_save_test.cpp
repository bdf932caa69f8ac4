// Brain saves through the C ABI, XML and binary: every route between brains and agents, the
// two-call buffer save (a change through any body between the calls gives the brain as it is now),
// corrupt or truncated binary saves refused with nothing handed out, NULL arguments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "verve_c.h"

namespace {

struct Format {
    const char* name;
    verve_result (*brainSave)(const verve_brain*, void*, size_t*);
};
const Format kFormats[] = {{"xml", verve_brain_save_memory}, {"binary", verve_brain_save_memory_binary}};

// The two calls: how big, then into a buffer of that size.
template <typename Handle, typename Save>
std::string saveOf(const Handle* handle, Save save) {
    size_t size = 0;
    EXPECT_EQ(save(handle, nullptr, &size), VERVE_OK) << verve_last_error();
    std::string bytes(size, '\0');
    EXPECT_EQ(save(handle, &bytes[0], &size), VERVE_OK) << verve_last_error();
    bytes.resize(size);
    return bytes;
}

std::string fileContents(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A brain (1 discrete sensor of 3 values, 1 continuous, 2 actions) and two bodies that have taken
// turns learning on it.
class BrainSaves : public ::testing::Test {
protected:
    void SetUp() override {
        verve_agent_desc d;
        verve_agent_desc_default(&d);
        d.num_discrete_sensors = 1;
        d.discrete_sensor_values[0] = 3;
        d.num_continuous_sensors = 1;
        d.resolution = 10;
        d.num_actions = 2;
        d.seed = 8;
        ASSERT_EQ(verve_brain_create(&d, &brain_), VERVE_OK) << verve_last_error();
        for (auto*& b : bodies_) ASSERT_EQ(verve_brain_create_body(brain_, &b), VERVE_OK) << verve_last_error();
        for (int t = 0; t < 100; ++t) step(bodies_[t % 2], t);
    }
    void TearDown() override {
        for (auto* b : bodies_) verve_agent_destroy(b);
        verve_brain_destroy(brain_);
    }
    static void step(verve_agent* body, int t) {
        const int32_t k = t % 3;
        const float x = std::sin(0.3f * static_cast<float>(t));
        uint32_t action = 0;
        ASSERT_EQ(verve_agent_update(body, t % 4 == 0 ? 1.0f : 0.0f, &k, 1, &x, 1, 0.1f, &action), VERVE_OK);
    }

    verve_brain* brain_ = nullptr;
    verve_agent* bodies_[2] = {};
};

TEST_F(BrainSaves, BinaryRoundTripsBetweenBrainsAndAgentsAreExact) {
    const std::string bytes = saveOf(brain_, verve_brain_save_memory_binary);
    const std::string xml = saveOf(brain_, verve_brain_save_memory);
    ASSERT_EQ(bytes.compare(0, 8, "VERVEBIN"), 0);
    EXPECT_LT(bytes.size(), xml.size());

    // brain -> binary -> brain: the same brain, saving to the same bytes in both formats.
    verve_brain* copy = nullptr;
    ASSERT_EQ(verve_brain_load_memory(bytes.data(), bytes.size(), &copy), VERVE_OK) << verve_last_error();
    uint32_t a = 0, b = 0;
    EXPECT_EQ(verve_brain_get_rbf_count(brain_, &a), VERVE_OK);
    EXPECT_EQ(verve_brain_get_rbf_count(copy, &b), VERVE_OK);
    EXPECT_GT(a, 0u);
    EXPECT_EQ(a, b);
    EXPECT_EQ(saveOf(copy, verve_brain_save_memory_binary), bytes);
    EXPECT_EQ(saveOf(copy, verve_brain_save_memory), xml);

    // brain -> binary -> agent, whose save loads as the same brain again.
    verve_agent* agent = nullptr;
    ASSERT_EQ(verve_agent_load_memory(bytes.data(), bytes.size(), &agent), VERVE_OK) << verve_last_error();
    const std::string agentBytes = saveOf(agent, verve_agent_save_memory_binary);
    verve_brain* back = nullptr;
    ASSERT_EQ(verve_brain_load_memory(agentBytes.data(), agentBytes.size(), &back), VERVE_OK) << verve_last_error();
    EXPECT_EQ(saveOf(back, verve_brain_save_memory_binary), bytes);

    // An agent's binary save (a body's: the brain plus its short-term memory) -> brain.
    const std::string bodyBytes = saveOf(bodies_[0], verve_agent_save_memory_binary);
    ASSERT_EQ(bodyBytes.compare(0, 8, "VERVEBIN"), 0);
    verve_brain* fromBody = nullptr;
    ASSERT_EQ(verve_brain_load_memory(bodyBytes.data(), bodyBytes.size(), &fromBody), VERVE_OK) << verve_last_error();
    EXPECT_EQ(saveOf(fromBody, verve_brain_save_memory_binary), bytes);

    // The XML save loads as the brain the binary one holds.
    verve_brain* fromXml = nullptr;
    ASSERT_EQ(verve_brain_load_memory(xml.data(), xml.size(), &fromXml), VERVE_OK) << verve_last_error();
    EXPECT_EQ(saveOf(fromXml, verve_brain_save_memory_binary), bytes);
    for (auto* x : {copy, back, fromBody, fromXml}) verve_brain_destroy(x);
    verve_agent_destroy(agent);
}

TEST_F(BrainSaves, BinaryFilesLoadAsBrainsAndAsAgents) {
    const std::string path = ::testing::TempDir() + "verve_brain_save_test.bin";
    ASSERT_EQ(verve_brain_save_binary(brain_, path.c_str()), VERVE_OK) << verve_last_error();
    const std::string bytes = fileContents(path);
    EXPECT_EQ(bytes, saveOf(brain_, verve_brain_save_memory_binary));
    verve_brain* loaded = nullptr;
    ASSERT_EQ(verve_brain_load(path.c_str(), &loaded), VERVE_OK) << verve_last_error();
    EXPECT_EQ(saveOf(loaded, verve_brain_save_memory_binary), bytes);
    verve_agent* agent = nullptr;
    EXPECT_EQ(verve_agent_load(path.c_str(), &agent), VERVE_OK) << verve_last_error();
    verve_agent_destroy(agent);
    verve_brain_destroy(loaded);

    // A damaged file is refused and hands out nothing.
    std::string damaged = bytes;
    damaged[damaged.size() / 2] = static_cast<char>(damaged[damaged.size() / 2] ^ 4);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << damaged;
    verve_brain* none = nullptr;
    EXPECT_EQ(verve_brain_load(path.c_str(), &none), VERVE_ERROR_FORMAT);
    EXPECT_NE(std::string(verve_last_error()).find("checksum"), std::string::npos) << verve_last_error();
    EXPECT_EQ(none, nullptr);
    std::remove(path.c_str());

    EXPECT_EQ(verve_brain_save_binary(brain_, "/nonexistent/dir/brain.bin"), VERVE_ERROR_IO);
    EXPECT_NE(std::string(verve_last_error()).find("/nonexistent/dir/brain.bin"), std::string::npos) << verve_last_error();
}

TEST_F(BrainSaves, CorruptOrTruncatedBinarySavesAreRefusedAndHandOutNothing) {
    const std::string bytes = saveOf(brain_, verve_brain_save_memory_binary);
    verve_brain* none = nullptr;
    for (std::size_t cut = 0; cut < bytes.size(); ++cut) {
        ASSERT_EQ(verve_brain_load_memory(bytes.data(), cut, &none), VERVE_ERROR_FORMAT) << "cut at " << cut;
        ASSERT_GT(std::string(verve_last_error()).size(), 20u) << "cut at " << cut;
    }
    for (std::size_t at = 0; at < bytes.size(); ++at) {
        std::string s = bytes;
        s[at] = static_cast<char>(s[at] ^ 0x20);
        const verve_result r = verve_brain_load_memory(s.data(), s.size(), &none);
        // A flip in the format version's bytes may read as a newer version.
        const bool inVersion = at >= 8 && at < 12;
        ASSERT_TRUE(r == VERVE_ERROR_FORMAT || (inVersion && r == VERVE_ERROR_VERSION)) << "byte " << at << ": " << r;
    }
    EXPECT_EQ(none, nullptr);
}

// The size query, a buffer one byte short (refused, untouched, the size needed reported), then
// the save itself, which loads and saves again to the same bytes.
TEST_F(BrainSaves, TwoCallsInEitherFormat) {
    for (const Format& f : kFormats) {
        size_t size = 0;
        ASSERT_EQ(f.brainSave(brain_, nullptr, &size), VERVE_OK) << f.name;
        ASSERT_GT(size, 0u);
        std::string small(size - 1, 'z');
        size_t capacity = small.size();
        EXPECT_EQ(f.brainSave(brain_, &small[0], &capacity), VERVE_ERROR_BUFFER_TOO_SMALL) << f.name;
        EXPECT_EQ(capacity, size) << f.name;
        EXPECT_EQ(small, std::string(size - 1, 'z')) << f.name;
        std::string bytes(size + 100, '\0');
        capacity = bytes.size();
        ASSERT_EQ(f.brainSave(brain_, &bytes[0], &capacity), VERVE_OK) << f.name;
        EXPECT_EQ(capacity, size) << f.name;
        bytes.resize(capacity);
        verve_brain* copy = nullptr;
        ASSERT_EQ(verve_brain_load_memory(bytes.data(), bytes.size(), &copy), VERVE_OK) << f.name << verve_last_error();
        EXPECT_EQ(saveOf(copy, f.brainSave), bytes) << f.name;
        verve_brain_destroy(copy);
    }
}

// The size query keeps its bytes for the call with a buffer; a change through any body in between
// (an update, an episode's end, a batch update) must give the brain as it is now.
TEST_F(BrainSaves, AChangeThroughAnyBodyBetweenTheTwoCallsGivesTheBrainAsItIsNow) {
    verve_batch_desc bd;
    ASSERT_EQ(verve_batch_desc_default(&bd), VERVE_OK);
    bd.worker_count = 1;
    verve_batch* batch = nullptr;
    ASSERT_EQ(verve_batch_create(&bd, &batch), VERVE_OK) << verve_last_error();
    int t = 100;
    const std::function<void(verve_agent*)> changes[] = {
        [&](verve_agent* body) { step(body, t++); },
        [&](verve_agent* body) { ASSERT_EQ(verve_agent_end_episode(body, -1.0f), VERVE_OK); },
        [&](verve_agent* body) {
            const float reward = 1.0f, x = 0.25f;
            const int32_t k = 1;
            uint32_t action = 0;
            ASSERT_EQ(verve_batch_update(batch, &body, 1, &reward, &k, nullptr, 1, &x, nullptr, 1, 0.1f, &action, nullptr),
                      VERVE_OK) << verve_last_error();
        },
    };
    for (const Format& f : kFormats) {
        for (std::size_t c = 0; c < std::size(changes); ++c) {
            for (verve_agent* body : bodies_) {
                step(body, t++);  // live traces, so that an episode's end changes the weights
                const std::string was = saveOf(brain_, f.brainSave);
                size_t size = 0;
                ASSERT_EQ(f.brainSave(brain_, nullptr, &size), VERVE_OK);  // keeps the bytes
                changes[c](body);
                std::string now(size + 4096, '\0');
                size = now.size();
                ASSERT_EQ(f.brainSave(brain_, &now[0], &size), VERVE_OK) << verve_last_error();
                now.resize(size);
                EXPECT_NE(now, was) << f.name << ", change " << c << ": the save from before it was delivered";
                EXPECT_EQ(now, saveOf(brain_, f.brainSave)) << f.name << ", change " << c;
            }
        }
    }
    verve_batch_destroy(batch);
}

TEST_F(BrainSaves, NullArgumentsAreRefused) {
    size_t size = 0;
    char byte = 0;
    EXPECT_EQ(verve_brain_save_binary(nullptr, "brain.bin"), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_brain_save_binary(brain_, nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(verve_last_error()).find("path"), std::string::npos) << verve_last_error();
    for (const Format& f : kFormats) {
        EXPECT_EQ(f.brainSave(nullptr, nullptr, &size), VERVE_ERROR_INVALID_ARGUMENT) << f.name;
        EXPECT_EQ(f.brainSave(brain_, nullptr, nullptr), VERVE_ERROR_INVALID_ARGUMENT) << f.name;
        EXPECT_EQ(f.brainSave(brain_, &byte, nullptr), VERVE_ERROR_INVALID_ARGUMENT) << f.name;
        EXPECT_NE(std::string(verve_last_error()).find("size"), std::string::npos) << verve_last_error();
    }
    EXPECT_EQ(byte, 0);
    verve_brain* out = nullptr;
    EXPECT_EQ(verve_brain_load_memory(nullptr, 10, &out), VERVE_ERROR_INVALID_ARGUMENT);
    const std::string bytes = saveOf(brain_, verve_brain_save_memory_binary);
    EXPECT_EQ(verve_brain_load_memory(bytes.data(), bytes.size(), nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(out, nullptr);
}

}  // namespace
