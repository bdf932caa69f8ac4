// Host hooks: every block Verve allocates goes through the host's allocator (and back), an update
// after warm-up allocates nothing, warnings reach the log, and hooks change only while Verve
// holds no memory.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "hardening_support.hpp"
#include "memory_hooks.hpp"

namespace verve::hardening {
namespace {

struct Log {
    std::vector<std::string> messages;
    static void VERVE_CALL record(void* user, verve_log_level level, const char* message) {
        EXPECT_EQ(level, VERVE_LOG_WARNING);
        static_cast<Log*>(user)->messages.emplace_back(message);
    }
};

class Hooks : public ::testing::Test {
protected:
    void install(verve_log_fn log = nullptr, void* user = nullptr) {
        const verve_hooks h = allocator_.hooks(log, user);
        ASSERT_EQ(verve_set_hooks(&h), VERVE_OK) << lastError();
    }
    void TearDown() override {
        EXPECT_EQ(verve_set_hooks(nullptr), VERVE_OK) << lastError();
        // Everything that went out through the hook came back through it.
        EXPECT_EQ(allocator_.allocations.load(), allocator_.frees.load());
    }
    CountingAllocator allocator_;
};

// 40 distinct observations, visited in turn: after one lap every RBF exists.
verve_result lap(verve_agent* agent, int i, float reward = 0.1f) {
    const int32_t disc = i % 3;
    const float c[2] = {std::sin(0.5f * static_cast<float>(i % 40)), std::cos(0.3f * static_cast<float>(i % 40))};
    uint32_t action = 0;
    return verve_agent_update(agent, reward, &disc, 1, c, 2, 0.1f, &action);
}

TEST_F(Hooks, EveryBlockGoesThroughTheHostAllocator) {
    install();
    verve_agent* agent = createOrFail(mixedDesc(true));
    for (int i = 0; i < 100; ++i) ASSERT_EQ(lap(agent, i), VERVE_OK);
    const std::string xml = saveToString(agent);
    verve_agent* loaded = nullptr;
    ASSERT_EQ(verve_agent_load_memory(xml.data(), xml.size(), &loaded), VERVE_OK) << lastError();
    EXPECT_EQ(verve_agent_update(agent, NAN, nullptr, 0, nullptr, 0, 0.1f, nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    verve_agent_destroy(loaded);
    verve_agent_destroy(agent);
    EXPECT_GT(allocator_.allocations.load(), 100);  // TearDown checks each came back
}

TEST_F(Hooks, AnUpdateAfterWarmUpAllocatesNothing) {
    install();
    verve_agent* agent = createOrFail(mixedDesc(true));
    for (int i = 0; i < 400; ++i) ASSERT_EQ(lap(agent, i), VERVE_OK);
    ASSERT_EQ(verve_agent_end_episode(agent, 1.0f), VERVE_OK);
    for (int i = 0; i < 40; ++i) ASSERT_EQ(lap(agent, i), VERVE_OK);
    uint32_t rbfs = 0;
    ASSERT_EQ(verve_agent_get_rbf_count(agent, &rbfs), VERVE_OK);
    const long before = allocator_.allocations.load();
    for (int i = 0; i < 400; ++i) ASSERT_EQ(lap(agent, i, i % 50 == 0 ? 1.0f : -0.05f), VERVE_OK);
    ASSERT_EQ(verve_agent_end_episode(agent, -1.0f), VERVE_OK);
    verve_agent_stats stats{};
    stats.struct_size = sizeof stats;
    ASSERT_EQ(verve_agent_get_stats(agent, &stats), VERVE_OK);
    EXPECT_EQ(allocator_.allocations.load() - before, 0);
    EXPECT_EQ(stats.rbf_count, rbfs);  // the warm-up made every RBF these observations need
    EXPECT_GT(stats.planning_steps + stats.steps, 0u);
    verve_agent_destroy(agent);
}

// A memory save's two calls serialise once: the call with a buffer after a size query only copies
// the kept bytes (serialising again would allocate), for agents and brains, in either format.
TEST_F(Hooks, AMemorySaveSerialisesOnceForItsTwoCalls) {
    install();
    verve_agent* agent = createOrFail(mixedDesc(true));
    verve_brain* brain = nullptr;
    const verve_agent_desc d = mixedDesc(false);
    ASSERT_EQ(verve_brain_create(&d, &brain), VERVE_OK) << lastError();
    verve_agent* body = nullptr;
    ASSERT_EQ(verve_brain_create_body(brain, &body), VERVE_OK) << lastError();
    for (int i = 0; i < 100; ++i) {
        ASSERT_EQ(lap(agent, i), VERVE_OK);
        ASSERT_EQ(lap(body, i), VERVE_OK);
    }
    // Allocations made by the size query and by the call with a buffer.
    auto allocationsOf = [&](auto save, const auto* handle) {
        const long start = allocator_.allocations.load();
        size_t size = 0;
        EXPECT_EQ(save(handle, nullptr, &size), VERVE_OK) << lastError();
        const long afterQuery = allocator_.allocations.load();
        std::string bytes(size, '\0');
        EXPECT_EQ(save(handle, &bytes[0], &size), VERVE_OK) << lastError();
        return std::make_pair(afterQuery - start, allocator_.allocations.load() - afterQuery);
    };
    const std::pair<long, long> counts[] = {
        allocationsOf(verve_agent_save_memory, agent),
        allocationsOf(verve_agent_save_memory_binary, agent),
        allocationsOf(verve_brain_save_memory, brain),
        allocationsOf(verve_brain_save_memory_binary, brain),
    };
    for (std::size_t i = 0; i < std::size(counts); ++i) {
        EXPECT_GT(counts[i].first, 0) << "save " << i << ": the size query serialises";
        EXPECT_EQ(counts[i].second, 0) << "save " << i << ": the call with a buffer serialised again";
    }
    verve_agent_destroy(body);
    verve_brain_destroy(brain);
    verve_agent_destroy(agent);
}

TEST_F(Hooks, HooksChangeOnlyWhileVerveHoldsNoMemory) {
    install();
    verve_agent* agent = createOrFail(mixedDesc(true));
    const verve_hooks h = allocator_.hooks();
    EXPECT_EQ(verve_set_hooks(&h), VERVE_ERROR_INVALID_STATE);
    EXPECT_NE(lastError().find("destroy"), std::string::npos) << lastError();
    EXPECT_EQ(verve_set_hooks(nullptr), VERVE_ERROR_INVALID_STATE);
    verve_agent_destroy(agent);
    verve_hooks half = h;
    half.free_fn = nullptr;
    EXPECT_EQ(verve_set_hooks(&half), VERVE_ERROR_INVALID_ARGUMENT);
    half = h;
    half.struct_size = 8;
    EXPECT_EQ(verve_set_hooks(&half), VERVE_ERROR_INVALID_ARGUMENT);
}

TEST_F(Hooks, ClampedRewardsAndTheBudgetAreReportedOnceAndCounted) {
    Log log;
    install(&Log::record, &log);
    verve_agent_desc d = mixedDesc(true);
    d.max_rbfs = 5;
    verve_agent* agent = createOrFail(d);
    for (int i = 0; i < 100; ++i) ASSERT_EQ(lap(agent, i, i < 2 ? 3.0f : 0.0f), VERVE_OK);
    ASSERT_EQ(verve_agent_end_episode(agent, -7.0f), VERVE_OK);
    verve_agent_stats stats{};
    stats.struct_size = sizeof stats;
    ASSERT_EQ(verve_agent_get_stats(agent, &stats), VERVE_OK);
    EXPECT_EQ(stats.clamped_rewards, 3u);
    EXPECT_GT(stats.rbf_budget_hits, 0u);
    EXPECT_EQ(stats.rbf_count, 5u);
    ASSERT_EQ(log.messages.size(), 2u);
    EXPECT_NE(log.messages[0].find("clamped"), std::string::npos) << log.messages[0];
    EXPECT_NE(log.messages[1].find("max_rbfs = 5"), std::string::npos) << log.messages[1];
    verve_agent_destroy(agent);
}

// The log hook runs inside an update: another thread calling the same agent right then is
// refused, deterministically (the stress tests in thread_test.cpp rely on timing).
struct Intruder {
    verve_agent* agent = nullptr;
    verve_result result = VERVE_OK;
    std::string message;
    static void VERVE_CALL during(void* user, verve_log_level, const char*) {
        auto* self = static_cast<Intruder*>(user);
        std::thread other([self] {
            float v = 0.0f;
            self->result = verve_agent_get_value(self->agent, &v);
            self->message = verve_last_error();
        });
        other.join();
    }
};

TEST_F(Hooks, ACallOverlappingAnotherOnTheSameAgentIsRefused) {
    Intruder intruder;
    install(&Intruder::during, &intruder);
    intruder.agent = createOrFail(mixedDesc(true));
    ASSERT_EQ(lap(intruder.agent, 0, 5.0f), VERVE_OK);  // the clamp warning fires inside the update
    EXPECT_EQ(intruder.result, VERVE_ERROR_INVALID_STATE);
    EXPECT_NE(intruder.message.find("in use"), std::string::npos) << intruder.message;
    float v = 0.0f;
    EXPECT_EQ(verve_agent_get_value(intruder.agent, &v), VERVE_OK);  // free again afterwards
    verve_agent_destroy(intruder.agent);
}

// Bodies of one brain share its weights: while one body is in a call, its brain and every other
// body of it are in use too, and a call on them from another thread is refused.
struct BrainIntruder {
    verve_brain* brain = nullptr;
    verve_agent* otherBody = nullptr;
    verve_result bodyResult = VERVE_OK;
    verve_result brainResult = VERVE_OK;
    static void VERVE_CALL during(void* user, verve_log_level, const char*) {
        auto* self = static_cast<BrainIntruder*>(user);
        std::thread other([self] {
            float v = 0.0f;
            uint32_t count = 0;
            self->bodyResult = verve_agent_get_value(self->otherBody, &v);
            self->brainResult = verve_brain_get_rbf_count(self->brain, &count);
        });
        other.join();
    }
};

TEST_F(Hooks, ACallOnAnotherBodyOfTheSameBrainIsRefused) {
    BrainIntruder intruder;
    install(&BrainIntruder::during, &intruder);
    const verve_agent_desc d = mixedDesc(false);
    ASSERT_EQ(verve_brain_create(&d, &intruder.brain), VERVE_OK) << lastError();
    verve_agent* body = nullptr;
    ASSERT_EQ(verve_brain_create_body(intruder.brain, &body), VERVE_OK) << lastError();
    ASSERT_EQ(verve_brain_create_body(intruder.brain, &intruder.otherBody), VERVE_OK) << lastError();
    ASSERT_EQ(lap(body, 0, 5.0f), VERVE_OK);  // the clamp warning fires inside the update
    EXPECT_EQ(intruder.bodyResult, VERVE_ERROR_INVALID_STATE);
    EXPECT_EQ(intruder.brainResult, VERVE_ERROR_INVALID_STATE);
    float v = 0.0f;
    EXPECT_EQ(verve_agent_get_value(intruder.otherBody, &v), VERVE_OK);  // free again afterwards
    uint32_t count = 0;
    EXPECT_EQ(verve_brain_get_rbf_count(intruder.brain, &count), VERVE_OK);
    verve_agent_destroy(intruder.otherBody);
    verve_agent_destroy(body);
    verve_brain_destroy(intruder.brain);
}

}  // namespace
}  // namespace verve::hardening
