// More than 16 sensors through the C ABI (issue 30): the V8 struct's arrays for sensors 16..63,
// older hosts' structs (V7 and before: 16 of each kind) still accepted and refused beyond 16, the
// lattice limit (JOINT or a CUSTOM group over more than 16 sensors), saves, batches and brains.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "verve_c.h"

namespace {

constexpr uint32_t kSensors = 32;

std::string lastError() { return verve_last_error(); }

// 32 discrete sensors of 1-2 values (their product stays small) and 32 continuous ones, every
// fifth circular, AUTO groups (32 singles + 31 pairs = 63 lattices).
verve_agent_desc desc32() {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_discrete_sensors = kSensors;
    d.num_continuous_sensors = kSensors;
    for (uint32_t i = 0; i < kSensors; ++i) {
        const uint32_t values = i % 8 == 0 ? 2u : 1u;
        const uint8_t circular = i % 5 == 0 ? 1 : 0;
        if (i < VERVE_MAX_DISCRETE_SENSORS) {
            d.discrete_sensor_values[i] = values;
            d.continuous_sensor_circular[i] = circular;
        } else {
            d.more_discrete_sensor_values[i - VERVE_MAX_DISCRETE_SENSORS] = values;
            d.more_continuous_sensor_circular[i - VERVE_MAX_CONTINUOUS_SENSORS] = circular;
        }
    }
    d.num_actions = 4;
    d.seed = 7;
    return d;
}

void expectRefusedSaying(const verve_agent_desc& d, const char* says) {
    verve_agent* agent = nullptr;
    EXPECT_EQ(verve_agent_create(&d, &agent), VERVE_ERROR_INVALID_ARGUMENT) << says;
    EXPECT_EQ(agent, nullptr);
    EXPECT_NE(lastError().find(says), std::string::npos) << lastError();
}

struct Obs {
    int32_t discrete[kSensors];
    float continuous[kSensors];
};

Obs observation(int t) {
    Obs o{};
    for (uint32_t i = 0; i < kSensors; ++i) {
        o.discrete[i] = i % 8 == 0 ? (t / 3 + static_cast<int>(i)) % 2 : 0;
        o.continuous[i] = 0.9f * std::sin(0.1f * static_cast<float>(t) * (0.3f + 0.17f * static_cast<float>(i)) + static_cast<float>(i));
    }
    return o;
}

uint32_t step(verve_agent* agent, int t) {
    const Obs o = observation(t);
    uint32_t action = 99;
    EXPECT_EQ(verve_agent_update(agent, std::sin(0.05f * static_cast<float>(t)), o.discrete, kSensors, o.continuous,
                                 kSensors, 0.1f, &action),
              VERVE_OK)
        << lastError();
    return action;
}

verve_agent* create(const verve_agent_desc& d) {
    verve_agent* agent = nullptr;
    EXPECT_EQ(verve_agent_create(&d, &agent), VERVE_OK) << lastError();
    return agent;
}

}  // namespace

TEST(CApiManySensors, V8StartsWhereV7EndedAndDefaultsFillTheNewArrays) {
    EXPECT_EQ(VERVE_AGENT_DESC_SIZE_V7, offsetof(verve_agent_desc, num_continuous_actions) + sizeof(uint64_t));
    EXPECT_EQ(VERVE_AGENT_DESC_SIZE_V8, sizeof(verve_agent_desc));
    EXPECT_EQ(VERVE_AGENT_DESC_SIZE_V8, VERVE_AGENT_DESC_SIZE_V7 + 48 * 4 + 48);
    EXPECT_EQ(VERVE_MAX_DISCRETE_SENSORS, 16);  // unchanged: V1-V7 hosts' arrays
    EXPECT_EQ(VERVE_MAX_CONTINUOUS_SENSORS, 16);
    EXPECT_EQ(VERVE_MAX_SENSORS, 64);

    unsigned char memory[sizeof(verve_agent_desc)];
    std::memset(memory, 0xAB, sizeof memory);
    verve_agent_desc* d = reinterpret_cast<verve_agent_desc*>(memory);
    ASSERT_EQ(verve_agent_desc_init(d, VERVE_AGENT_DESC_SIZE_V8), VERVE_OK);
    for (uint32_t v : d->more_discrete_sensor_values) EXPECT_EQ(v, 0u);
    for (uint8_t c : d->more_continuous_sensor_circular) EXPECT_EQ(c, 0u);
    // A V7 host's init writes only its bytes.
    std::memset(memory, 0xAB, sizeof memory);
    ASSERT_EQ(verve_agent_desc_init(d, VERVE_AGENT_DESC_SIZE_V7), VERVE_OK);
    for (std::size_t k = VERVE_AGENT_DESC_SIZE_V7; k < sizeof memory; ++k) ASSERT_EQ(memory[k], 0xAB) << "byte " << k;
}

TEST(CApiManySensors, AV8DescOf32SensorsRoundTrips) {
    const verve_agent_desc d = desc32();
    verve_agent* agent = create(d);
    ASSERT_NE(agent, nullptr);
    verve_agent_desc back;
    verve_agent_desc_default(&back);
    ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK) << lastError();
    EXPECT_EQ(back.num_discrete_sensors, kSensors);
    EXPECT_EQ(back.num_continuous_sensors, kSensors);
    EXPECT_EQ(std::memcmp(back.discrete_sensor_values, d.discrete_sensor_values, sizeof d.discrete_sensor_values), 0);
    EXPECT_EQ(std::memcmp(back.more_discrete_sensor_values, d.more_discrete_sensor_values, sizeof d.more_discrete_sensor_values), 0);
    EXPECT_EQ(std::memcmp(back.continuous_sensor_circular, d.continuous_sensor_circular, sizeof d.continuous_sensor_circular), 0);
    EXPECT_EQ(std::memcmp(back.more_continuous_sensor_circular, d.more_continuous_sensor_circular,
                          sizeof d.more_continuous_sensor_circular),
              0);
    for (int t = 0; t < 200; ++t) ASSERT_LT(step(agent, t), 4u);
    // A wrong count is refused as with 16.
    const Obs o = observation(0);
    uint32_t action = 0;
    EXPECT_EQ(verve_agent_update(agent, 0.0f, o.discrete, kSensors, o.continuous, kSensors - 1, 0.1f, &action),
              VERVE_ERROR_INVALID_ARGUMENT);
    // A V7 host cannot hold this agent's description: refused, its struct untouched.
    unsigned char memory[sizeof(verve_agent_desc)];
    std::memset(memory, 0xCD, sizeof memory);
    verve_agent_desc* v7 = reinterpret_cast<verve_agent_desc*>(memory);
    v7->struct_size = VERVE_AGENT_DESC_SIZE_V7;
    EXPECT_EQ(verve_agent_get_desc(agent, v7), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(lastError().find("VERVE_AGENT_DESC_SIZE_V8"), std::string::npos) << lastError();
    for (std::size_t k = sizeof(uint32_t); k < sizeof memory; ++k) ASSERT_EQ(memory[k], 0xCD) << "byte " << k;
    verve_agent_destroy(agent);
}

TEST(CApiManySensors, OlderStructsKeepWorkingUpTo16AndRefuseMore) {
    for (uint32_t size : {VERVE_AGENT_DESC_SIZE_V1, VERVE_AGENT_DESC_SIZE_V5, VERVE_AGENT_DESC_SIZE_V7}) {
        unsigned char memory[sizeof(verve_agent_desc)];
        std::memset(memory, 0xAB, sizeof memory);  // beyond `size`: not the host's, never read
        verve_agent_desc* d = reinterpret_cast<verve_agent_desc*>(memory);
        ASSERT_EQ(verve_agent_desc_init(d, size), VERVE_OK);
        d->num_continuous_sensors = 16;
        d->num_actions = 3;
        verve_agent* agent = nullptr;
        ASSERT_EQ(verve_agent_create(d, &agent), VERVE_OK) << size << ": " << lastError();
        verve_agent_desc back;
        std::memset(&back, 0xCD, sizeof back);
        back.struct_size = size;
        ASSERT_EQ(verve_agent_get_desc(agent, &back), VERVE_OK) << lastError();
        EXPECT_EQ(back.num_continuous_sensors, 16u);
        verve_agent_destroy(agent);

        d->num_continuous_sensors = 17;
        EXPECT_EQ(verve_agent_create(d, &agent), VERVE_ERROR_INVALID_ARGUMENT) << size;
        EXPECT_NE(lastError().find("num_continuous_sensors is 17, at most 16 (struct_size " + std::to_string(size) + " holds 16"),
                  std::string::npos)
            << lastError();
        d->num_continuous_sensors = 0;
        d->num_discrete_sensors = 32;
        EXPECT_EQ(verve_agent_create(d, &agent), VERVE_ERROR_INVALID_ARGUMENT) << size;
        EXPECT_NE(lastError().find("num_discrete_sensors is 32, at most 16"), std::string::npos) << lastError();
    }
}

TEST(CApiManySensors, BadAndOverLimitDescsAreRefusedClearly) {
    verve_agent_desc d = desc32();
    d.num_continuous_sensors = 65;
    expectRefusedSaying(d, "num_continuous_sensors is 65, at most 64");
    d = desc32();
    d.num_discrete_sensors = 0xFFFFFFFFu;
    expectRefusedSaying(d, "num_discrete_sensors is 4294967295, at most 64");
    d = desc32();
    d.more_continuous_sensor_circular[3] = 7;
    expectRefusedSaying(d, "more_continuous_sensor_circular[3] must be 0 or 1");
    d = desc32();
    d.more_discrete_sensor_values[5] = 0;
    expectRefusedSaying(d, "discrete_sensor_values[21] must be at least 1");
    // One lattice spans at most 16 sensors.
    d = desc32();
    d.sensor_grouping = VERVE_GROUPING_JOINT;
    expectRefusedSaying(d, "JOINT sensor_grouping puts all 32 continuous sensors in one lattice, which spans at most 16");
    d = desc32();
    d.sensor_grouping = VERVE_GROUPING_CUSTOM;
    d.num_sensor_groups = 2;
    d.sensor_groups[0] = 0x1FFFFull;          // 17 sensors
    d.sensor_groups[1] = 0xFFFFFFFFull << 0;  // all 32
    expectRefusedSaying(d, "sensor_groups[0] spans 17 continuous sensors, one lattice at most 16");
    // AUTO's lattice per sensor and per pair: 2n - 1 lattices, so up to 32 sensors.
    d = desc32();
    d.num_continuous_sensors = 33;
    expectRefusedSaying(d, "33 continuous sensors make 65 AUTO sensor_groups");
    // CUSTOM groups read 64: four lattices of 16.
    d.num_continuous_sensors = 64;
    d.sensor_grouping = VERVE_GROUPING_CUSTOM;
    d.num_sensor_groups = 4;
    for (int g = 0; g < 4; ++g) d.sensor_groups[g] = 0xFFFFull << (16 * g);
    verve_agent* agent = create(d);
    ASSERT_NE(agent, nullptr);
    std::vector<float> c(64, 0.25f);
    std::vector<int32_t> disc(kSensors, 0);
    uint32_t action = 0;
    EXPECT_EQ(verve_agent_update(agent, 0.0f, disc.data(), kSensors, c.data(), 64, 0.1f, &action), VERVE_OK) << lastError();
    verve_agent_destroy(agent);
}

TEST(CApiManySensors, XmlAndBinarySavesOf32SensorsKeepActionsIdentical) {
    verve_agent* agent = create(desc32());
    ASSERT_NE(agent, nullptr);
    for (int t = 0; t < 300; ++t) step(agent, t);
    for (const bool binary : {false, true}) {
        size_t size = 0;
        ASSERT_EQ(binary ? verve_agent_save_memory_binary(agent, nullptr, &size) : verve_agent_save_memory(agent, nullptr, &size),
                  VERVE_OK);
        std::vector<char> bytes(size);
        ASSERT_EQ(binary ? verve_agent_save_memory_binary(agent, bytes.data(), &size)
                         : verve_agent_save_memory(agent, bytes.data(), &size),
                  VERVE_OK)
            << lastError();
        verve_agent* loaded = nullptr;
        ASSERT_EQ(verve_agent_load_memory(bytes.data(), size, &loaded), VERVE_OK) << lastError();
        verve_agent_desc back;
        verve_agent_desc_default(&back);
        ASSERT_EQ(verve_agent_get_desc(loaded, &back), VERVE_OK);
        EXPECT_EQ(back.num_continuous_sensors, kSensors);
        EXPECT_EQ(back.more_continuous_sensor_circular[4], 1u);  // sensor 20
        for (int t = 300; t < 400; ++t) ASSERT_EQ(step(agent, t), step(loaded, t)) << (binary ? "binary" : "XML") << " t " << t;
        verve_agent_destroy(loaded);
    }
    verve_agent_destroy(agent);
}

TEST(CApiManySensors, A32SensorAgentInABatchMatchesItsOwnUpdates) {
    verve_agent* batched[2] = {create(desc32()), create(desc32())};
    verve_agent* alone = create(desc32());
    verve_batch_desc bd;
    ASSERT_EQ(verve_batch_desc_default(&bd), VERVE_OK);
    bd.worker_count = 2;
    verve_batch* batch = nullptr;
    ASSERT_EQ(verve_batch_create(&bd, &batch), VERVE_OK) << lastError();
    for (int t = 0; t < 150; ++t) {
        const Obs o = observation(t);
        std::vector<int32_t> disc(o.discrete, o.discrete + kSensors);
        disc.insert(disc.end(), o.discrete, o.discrete + kSensors);
        std::vector<float> cont(o.continuous, o.continuous + kSensors);
        cont.insert(cont.end(), o.continuous, o.continuous + kSensors);
        const float reward = std::sin(0.05f * static_cast<float>(t));
        const float rewards[2] = {reward, reward};
        uint32_t actions[2] = {99, 99};
        ASSERT_EQ(verve_batch_update(batch, batched, 2, rewards, disc.data(), nullptr, 2 * kSensors, cont.data(), nullptr,
                                     2 * kSensors, 0.1f, actions, nullptr),
                  VERVE_OK)
            << lastError();
        const uint32_t own = step(alone, t);
        EXPECT_EQ(actions[0], own) << t;
        EXPECT_EQ(actions[1], own) << t;
    }
    verve_batch_destroy(batch);
    for (verve_agent* a : batched) verve_agent_destroy(a);
    verve_agent_destroy(alone);
}

TEST(CApiManySensors, AShared32SensorBrainLearnsFromItsBodiesAndSaves) {
    const verve_agent_desc d = desc32();
    verve_brain* brain = nullptr;
    ASSERT_EQ(verve_brain_create(&d, &brain), VERVE_OK) << lastError();
    verve_agent* bodies[3] = {};
    for (auto& b : bodies) ASSERT_EQ(verve_brain_create_body(brain, &b), VERVE_OK) << lastError();
    for (int t = 0; t < 100; ++t) {
        for (int k = 0; k < 3; ++k) ASSERT_LT(step(bodies[k], t + 7 * k), 4u);
    }
    uint32_t rbfs = 0;
    ASSERT_EQ(verve_brain_get_rbf_count(brain, &rbfs), VERVE_OK);
    EXPECT_GT(rbfs, 63u);  // at least one RBF in each of the 63 lattices
    size_t size = 0;
    ASSERT_EQ(verve_brain_save_memory(brain, nullptr, &size), VERVE_OK);
    std::vector<char> bytes(size);
    ASSERT_EQ(verve_brain_save_memory(brain, bytes.data(), &size), VERVE_OK) << lastError();
    verve_brain* loaded = nullptr;
    ASSERT_EQ(verve_brain_load_memory(bytes.data(), size, &loaded), VERVE_OK) << lastError();
    uint32_t loadedRbfs = 0;
    ASSERT_EQ(verve_brain_get_rbf_count(loaded, &loadedRbfs), VERVE_OK);
    EXPECT_EQ(loadedRbfs, rbfs);
    verve_brain_destroy(loaded);
    for (verve_agent* b : bodies) verve_agent_destroy(b);
    verve_brain_destroy(brain);
}

// A recording is shaped like its agent: 40 continuous sensors (Custom groups; Auto stops at 32)
// are recorded, saved, loaded and replayed.
TEST(CApiManySensors, ARecordingOf40SensorsSavesLoadsAndReplays) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_continuous_sensors = 40;
    d.sensor_grouping = VERVE_GROUPING_CUSTOM;
    d.num_sensor_groups = 3;
    d.sensor_groups[0] = 0xFFFFull;
    d.sensor_groups[1] = 0xFFFFull << 16;
    d.sensor_groups[2] = 0xFFull << 32;
    d.num_actions = 3;
    verve_agent* agent = create(d);
    ASSERT_NE(agent, nullptr);
    verve_recording* recording = nullptr;
    ASSERT_EQ(verve_recording_create(agent, &recording), VERVE_OK) << lastError();
    std::vector<float> c(40);
    for (int t = 0; t < 20; ++t) {
        for (int i = 0; i < 40; ++i) c[i] = std::sin(0.2f * static_cast<float>(t + i));
        ASSERT_EQ(verve_recording_add_step(recording, 0.1f, nullptr, 0, c.data(), 40, 0.1f, static_cast<uint32_t>(t % 3)), VERVE_OK)
            << lastError();
    }
    size_t size = 0;
    ASSERT_EQ(verve_recording_save_memory(recording, nullptr, &size), VERVE_OK);
    std::vector<char> bytes(size);
    ASSERT_EQ(verve_recording_save_memory(recording, bytes.data(), &size), VERVE_OK) << lastError();
    verve_recording* loaded = nullptr;
    ASSERT_EQ(verve_recording_load_memory(bytes.data(), size, &loaded), VERVE_OK) << lastError();
    EXPECT_EQ(verve_agent_replay(agent, loaded), VERVE_OK) << lastError();
    verve_recording_destroy(loaded);
    verve_recording_destroy(recording);
    verve_agent_destroy(agent);
}
