// Recordings of demonstrated steps through the C ABI (docs/teaching.md, "Recordings"): what is
// recorded replays as the same demonstrated steps, the file round-trips through memory and disk,
// and bad entries, damaged files and mismatched agents are refused, changing nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "verve_c.h"

namespace {

verve_agent_desc petDesc(uint64_t seed) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_discrete_sensors = 1;
    d.discrete_sensor_values[0] = 4;
    d.num_continuous_sensors = 2;
    d.num_actions = 3;
    d.seed = seed;
    return d;
}

verve_agent* make(const verve_agent_desc& d) {
    verve_agent* a = nullptr;
    EXPECT_EQ(verve_agent_create(&d, &a), VERVE_OK) << verve_last_error();
    return a;
}

std::string agentBytes(const verve_agent* a) {
    size_t size = 0;
    EXPECT_EQ(verve_agent_save_memory_binary(a, nullptr, &size), VERVE_OK);
    std::string bytes(size, '\0');
    EXPECT_EQ(verve_agent_save_memory_binary(a, &bytes[0], &size), VERVE_OK);
    return bytes;
}

std::string recordingBytes(const verve_recording* r) {
    size_t size = 0;
    EXPECT_EQ(verve_recording_save_memory(r, nullptr, &size), VERVE_OK) << verve_last_error();
    std::string bytes(size, '\0');
    EXPECT_EQ(verve_recording_save_memory(r, &bytes[0], &size), VERVE_OK) << verve_last_error();
    return bytes;
}

// Three short trials of a scripted driver, recorded and, in `direct`, shown as they happen.
void demonstrate(verve_recording* r, verve_agent* direct) {
    for (int trial = 0; trial < 3; ++trial) {
        for (int i = 0; i < 12; ++i) {
            const int32_t d = (i + trial) % 4;
            const float c[2] = {std::sin(0.7f * static_cast<float>(i)), 0.1f * static_cast<float>(trial)};
            const uint32_t action = static_cast<uint32_t>((i * 7 + trial) % 3);
            const float reward = i % 5 == 0 ? 0.5f : -0.05f;
            ASSERT_EQ(verve_recording_add_step(r, reward, &d, 1, c, 2, 0.1f, action), VERVE_OK) << verve_last_error();
            ASSERT_EQ(verve_agent_update_demonstrated(direct, reward, &d, 1, c, 2, 0.1f, nullptr, 0, action), VERVE_OK);
        }
        if (trial == 1) {
            ASSERT_EQ(verve_recording_add_truncation(r, -0.2f), VERVE_OK);
            ASSERT_EQ(verve_agent_truncate_episode(direct, -0.2f), VERVE_OK);
        } else {
            ASSERT_EQ(verve_recording_add_end_episode(r, 1.0f), VERVE_OK);
            ASSERT_EQ(verve_agent_end_episode(direct, 1.0f), VERVE_OK);
        }
    }
}

TEST(Recording, ReplaysAsTheDemonstratedStepsItHolds) {
    verve_agent* direct = make(petDesc(7));
    verve_agent* replayed = make(petDesc(7));
    verve_recording* r = nullptr;
    ASSERT_EQ(verve_recording_create(direct, &r), VERVE_OK) << verve_last_error();
    demonstrate(r, direct);
    uint64_t entries = 0;
    ASSERT_EQ(verve_recording_get_size(r, &entries), VERVE_OK);
    EXPECT_EQ(entries, 39u);

    // Through memory and through a file, the same bytes; replayed, the same agent.
    const std::string bytes = recordingBytes(r);
    verve_recording* fromMemory = nullptr;
    ASSERT_EQ(verve_recording_load_memory(bytes.data(), bytes.size(), &fromMemory), VERVE_OK) << verve_last_error();
    EXPECT_EQ(recordingBytes(fromMemory), bytes);
    const std::string path = (std::filesystem::temp_directory_path() / "verve_recording_test.vrec").string();
    ASSERT_EQ(verve_recording_save(fromMemory, path.c_str()), VERVE_OK) << verve_last_error();
    verve_recording* fromFile = nullptr;
    ASSERT_EQ(verve_recording_load(path.c_str(), &fromFile), VERVE_OK) << verve_last_error();
    std::remove(path.c_str());
    EXPECT_EQ(recordingBytes(fromFile), bytes);
    ASSERT_EQ(verve_agent_replay(replayed, fromFile), VERVE_OK) << verve_last_error();
    EXPECT_EQ(agentBytes(replayed), agentBytes(direct));

    verve_recording_destroy(r);
    verve_recording_destroy(fromMemory);
    verve_recording_destroy(fromFile);
    verve_agent_destroy(direct);
    verve_agent_destroy(replayed);
}

TEST(Recording, BadEntriesDamagedFilesAndOtherAgentsAreRefusedAndChangeNothing) {
    verve_agent* agent = make(petDesc(3));
    verve_recording* r = nullptr;
    ASSERT_EQ(verve_recording_create(agent, &r), VERVE_OK);
    verve_agent* shown = make(petDesc(3));
    demonstrate(r, shown);
    verve_agent_destroy(shown);
    const std::string before = recordingBytes(r);
    const int32_t d = 1, badD = 4;
    const float c[2] = {0.2f, -0.3f}, nanC[2] = {std::numeric_limits<float>::quiet_NaN(), 0.0f};
    EXPECT_EQ(verve_recording_add_step(r, 0.0f, &badD, 1, c, 2, 0.1f, 0), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_recording_add_step(r, 0.0f, &d, 1, nanC, 2, 0.1f, 0), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_recording_add_step(r, 0.0f, &d, 1, c, 1, 0.1f, 0), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_recording_add_step(r, 0.0f, &d, 1, c, 2, 0.0f, 0), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_recording_add_step(r, 0.0f, &d, 1, c, 2, 0.1f, 3), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_recording_add_step(r, std::numeric_limits<float>::infinity(), &d, 1, c, 2, 0.1f, 0),
              VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_recording_add_step(r, 0.0f, nullptr, 1, c, 2, 0.1f, 0), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_recording_add_end_episode(r, std::numeric_limits<float>::quiet_NaN()), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_recording_add_step(nullptr, 0.0f, &d, 1, c, 2, 0.1f, 0), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(recordingBytes(r), before);

    // Damaged, cut, foreign and future files.
    verve_recording* out = nullptr;
    std::string flipped = before;
    flipped[flipped.size() / 2] ^= 0x10;
    EXPECT_EQ(verve_recording_load_memory(flipped.data(), flipped.size(), &out), VERVE_ERROR_FORMAT);
    EXPECT_NE(std::string(verve_last_error()).find("checksum"), std::string::npos) << verve_last_error();
    EXPECT_EQ(verve_recording_load_memory(before.data(), before.size() - 3, &out), VERVE_ERROR_FORMAT);
    EXPECT_EQ(verve_recording_load_memory("VERVEBIN", 8, &out), VERVE_ERROR_FORMAT);
    std::string future = before;
    future[8] = 3;  // format version 3
    EXPECT_EQ(verve_recording_load_memory(future.data(), future.size(), &out), VERVE_ERROR_VERSION);
    EXPECT_EQ(out, nullptr);

    // An agent with other sensors or actions: nothing is replayed.
    verve_agent_desc other = petDesc(3);
    other.num_actions = 4;
    verve_agent* stranger = make(other);
    const std::string strangerBefore = agentBytes(stranger);
    EXPECT_EQ(verve_agent_replay(stranger, r), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(verve_last_error()).find("not the agent's"), std::string::npos) << verve_last_error();
    EXPECT_EQ(agentBytes(stranger), strangerBefore);
    EXPECT_EQ(verve_agent_replay(agent, nullptr), VERVE_ERROR_INVALID_ARGUMENT);

    verve_recording_destroy(nullptr);
    verve_recording_destroy(r);
    verve_agent_destroy(stranger);
    verve_agent_destroy(agent);
}

}  // namespace

// The teacher's continuous actions (verve_agent_update_demonstrated_continuous and
// verve_recording_add_step_continuous): recorded, saved and replayed as the live calls; wrong
// counts, NULL, NaN and values outside [-1, 1] refused, changing nothing.
TEST(Recording, ContinuousActionsAreRecordedReplayedAndChecked) {
    verve_agent_desc d = petDesc(5);
    d.num_actions = 2;
    d.num_continuous_actions = 2;
    verve_agent* direct = make(d);
    verve_agent* replayed = make(d);
    verve_recording* r = nullptr;
    ASSERT_EQ(verve_recording_create(direct, &r), VERVE_OK) << verve_last_error();
    for (int i = 0; i < 20; ++i) {
        const int32_t disc = i % 4;
        const float c[2] = {std::sin(0.3f * static_cast<float>(i)), -0.2f};
        const float steer[2] = {c[0], i % 2 ? 1.0f : -1.0f};
        const uint32_t action = static_cast<uint32_t>(i % 2);
        ASSERT_EQ(verve_recording_add_step_continuous(r, -0.1f, &disc, 1, c, 2, 0.1f, action, steer, 2), VERVE_OK)
            << verve_last_error();
        ASSERT_EQ(verve_agent_update_demonstrated_continuous(direct, -0.1f, &disc, 1, c, 2, 0.1f, nullptr, 0, action, steer, 2),
                  VERVE_OK)
            << verve_last_error();
        float played[2] = {0, 0};
        ASSERT_EQ(verve_agent_get_continuous_action(direct, played, 2), VERVE_OK);
        EXPECT_EQ(played[0], steer[0]);
        EXPECT_EQ(played[1], steer[1]);
    }
    ASSERT_EQ(verve_recording_add_end_episode(r, 1.0f), VERVE_OK);
    ASSERT_EQ(verve_agent_end_episode(direct, 1.0f), VERVE_OK);
    const std::string bytes = recordingBytes(r);
    verve_recording* loaded = nullptr;
    ASSERT_EQ(verve_recording_load_memory(bytes.data(), bytes.size(), &loaded), VERVE_OK) << verve_last_error();
    ASSERT_EQ(verve_agent_replay(replayed, loaded), VERVE_OK) << verve_last_error();
    EXPECT_EQ(agentBytes(replayed), agentBytes(direct));

    const std::string agentBefore = agentBytes(direct);
    const int32_t disc = 0;
    const float c[2] = {0.0f, 0.0f};
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float bad[][2] = {{nan, 0.0f}, {0.0f, 1.5f}, {-1.01f, 0.0f}};
    for (const auto& values : bad) {
        EXPECT_EQ(verve_agent_update_demonstrated_continuous(direct, 0.0f, &disc, 1, c, 2, 0.1f, nullptr, 0, 0, values, 2),
                  VERVE_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(verve_last_error()).find("[-1, 1]"), std::string::npos) << verve_last_error();
        EXPECT_EQ(verve_recording_add_step_continuous(r, 0.0f, &disc, 1, c, 2, 0.1f, 0, values, 2), VERVE_ERROR_INVALID_ARGUMENT);
    }
    const float one[2] = {0.5f, 0.5f};
    EXPECT_EQ(verve_agent_update_demonstrated_continuous(direct, 0.0f, &disc, 1, c, 2, 0.1f, nullptr, 0, 0, one, 1),
              VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_agent_update_demonstrated_continuous(direct, 0.0f, &disc, 1, c, 2, 0.1f, nullptr, 0, 0, nullptr, 2),
              VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_recording_add_step_continuous(r, 0.0f, &disc, 1, c, 2, 0.1f, 0, one, 3), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_recording_add_step_continuous(r, 0.0f, &disc, 1, c, 2, 0.1f, 0, nullptr, 2), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_agent_update_demonstrated_continuous(nullptr, 0.0f, &disc, 1, c, 2, 0.1f, nullptr, 0, 0, one, 2),
              VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(agentBytes(direct), agentBefore);
    EXPECT_EQ(recordingBytes(r), bytes);

    // An agent with one continuous action cannot replay steps that hold two.
    d.num_continuous_actions = 1;
    verve_agent* other = make(d);
    EXPECT_EQ(verve_agent_replay(other, r), VERVE_ERROR_INVALID_ARGUMENT);
    verve_agent_destroy(other);
    verve_recording_destroy(loaded);
    verve_recording_destroy(r);
    verve_agent_destroy(replayed);
    verve_agent_destroy(direct);
}
