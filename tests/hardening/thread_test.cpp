// Threads: separate agents on many threads are independent (update, save, load, last_error);
// one agent used from two threads at once is refused with VERVE_ERROR_INVALID_STATE, never a
// crash or a silently wrong result. Run under ThreadSanitizer by scripts/tsan.sh.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "hardening_support.hpp"

namespace verve::hardening {
namespace {

verve_result step(verve_agent* agent, int i, uint32_t* action) {
    const int32_t disc = i % 3;
    const float cont[2] = {std::sin(0.1f * static_cast<float>(i)), std::cos(0.37f * static_cast<float>(i))};
    return verve_agent_update(agent, i % 7 == 0 ? 1.0f : -0.1f, &disc, 1, cont, 2, 0.1f, action);
}

TEST(Threads, SeparateAgentsOnManyThreadsAreIndependent) {
    constexpr int kThreads = 4;
    std::vector<std::string> failures(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
        threads.emplace_back([t, &failures] {
            std::string& fail = failures[t];
            verve_agent* agent = nullptr;
            const verve_agent_desc d = mixedDesc(t % 2 == 1, 100 + t);
            if (verve_agent_create(&d, &agent) != VERVE_OK) return void(fail = verve_last_error());
            const std::string path = ::testing::TempDir() + "/verve_thread_" + std::to_string(::getpid()) + "_" +
                                     std::to_string(t) + ".xml";
            for (int round = 0; round < 3 && fail.empty(); ++round) {
                uint32_t action = 0;
                for (int i = 0; i < 150; ++i) {
                    if (step(agent, i + 1000 * t, &action) != VERVE_OK) return void(fail = verve_last_error());
                }
                // A refused call sets this thread's message only.
                if (verve_agent_update(agent, NAN, nullptr, 0, nullptr, 0, 0.1f, &action) != VERVE_ERROR_INVALID_ARGUMENT ||
                    std::string(verve_last_error()).find("verve_agent_update") == std::string::npos) {
                    return void(fail = "refusal not reported on its own thread");
                }
                if (verve_agent_save(agent, path.c_str()) != VERVE_OK) return void(fail = verve_last_error());
                if (std::string(verve_last_error()) != "") return void(fail = "last error not cleared by success");
                verve_agent* loaded = nullptr;
                if (verve_agent_load(path.c_str(), &loaded) != VERVE_OK) return void(fail = verve_last_error());
                size_t size = 0;
                verve_agent_save_memory(loaded, nullptr, &size);
                std::string xml(size, '\0');
                if (verve_agent_save_memory(loaded, &xml[0], &size) != VERVE_OK) return void(fail = verve_last_error());
                verve_agent_destroy(agent);
                if (verve_agent_load_memory(xml.data(), size, &agent) != VERVE_OK) return void(fail = verve_last_error());
                // The reloaded agents act alike: nothing leaked between threads.
                for (int i = 0; i < 20; ++i) {
                    uint32_t a1 = 0, a2 = 1;
                    step(agent, i, &a1);
                    step(loaded, i, &a2);
                    if (a1 != a2) fail = "reloaded agents diverge at step " + std::to_string(i);
                }
                verve_agent_destroy(loaded);
            }
            verve_agent_destroy(agent);
        });
    }
    for (auto& th : threads) th.join();
    for (int t = 0; t < kThreads; ++t) EXPECT_EQ(failures[t], "") << "thread " << t;
}

// A memory save's two calls on one agent while another thread keeps changing another agent: each
// agent's kept save goes stale only with its own changes (a global change count once made the
// size query's own kept copy vanish mid-call).
TEST(Threads, MemorySavesIgnoreOtherAgentsChanges) {
    verve_agent* saved = createOrFail(mixedDesc(false, 11));
    verve_agent* busy = createOrFail(mixedDesc(true, 12));
    uint32_t action = 0;
    for (int i = 0; i < 50; ++i) ASSERT_EQ(step(saved, i, &action), VERVE_OK);
    std::atomic<bool> stop{false};
    std::thread changer([&] {
        uint32_t own = 0;
        for (int i = 0; !stop.load(); ++i) step(busy, i, &own);
    });
    std::string failure;
    std::string first;
    for (int round = 0; round < 300 && failure.empty(); ++round) {
        size_t size = 0;
        if (verve_agent_save_memory(saved, nullptr, &size) != VERVE_OK) failure = lastError();
        std::string bytes(size, '\0');
        if (failure.empty() && verve_agent_save_memory(saved, &bytes[0], &size) != VERVE_OK) failure = lastError();
        if (first.empty()) first = bytes;
        if (failure.empty() && bytes != first) failure = "the unchanged agent's save changed in round " + std::to_string(round);
    }
    stop = true;
    changer.join();
    EXPECT_EQ(failure, "");
    verve_agent_destroy(busy);
    verve_agent_destroy(saved);
}

// A brain's memory saves on one thread while another thread updates one of its bodies: each call
// runs alone or is refused, and every save delivered is whole (it loads), in either format. The
// size query's kept bytes are the brain's, and the body's updates make them stale.
TEST(Threads, BrainSavesWhileABodyLearnsAreWholeOrRefused) {
    verve_brain* brain = nullptr;
    const verve_agent_desc d = mixedDesc(false, 13);
    ASSERT_EQ(verve_brain_create(&d, &brain), VERVE_OK) << lastError();
    verve_agent* body = nullptr;
    ASSERT_EQ(verve_brain_create_body(brain, &body), VERVE_OK) << lastError();
    std::atomic<bool> stop{false};
    std::atomic<long> updates{0};
    std::atomic<int> learnerError{VERVE_OK};
    std::thread learner([&] {
        uint32_t action = 0;
        for (int i = 0; !stop.load() && learnerError.load() == VERVE_OK; ++i) {
            const verve_result r = step(body, i, &action);
            if (r == VERVE_OK) ++updates;
            else if (r != VERVE_ERROR_INVALID_STATE) learnerError = r;
            std::this_thread::yield();  // let the saver in now and then
        }
    });
    std::string failure;
    long delivered = 0;
    // Until 100 saves and 100 updates have gone through, or 10 s (a loaded machine) have passed.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    for (int round = 0; (delivered < 100 || updates.load() < 100) && failure.empty() &&
                        std::chrono::steady_clock::now() < deadline;
         ++round) {
        const auto save = round % 2 == 0 ? verve_brain_save_memory : verve_brain_save_memory_binary;
        size_t size = 0;
        verve_result r = save(brain, nullptr, &size);
        if (r == VERVE_ERROR_INVALID_STATE) continue;
        if (r != VERVE_OK) {
            failure = lastError();
            break;
        }
        std::string bytes(size + 65536, '\0');  // room for the RBFs the body may add meanwhile
        size = bytes.size();
        r = save(brain, &bytes[0], &size);
        // Refused, or the body added more RBFs than the room allows: the size is right, try again.
        if (r == VERVE_ERROR_INVALID_STATE || r == VERVE_ERROR_BUFFER_TOO_SMALL) continue;
        if (r != VERVE_OK) {
            failure = lastError();
            break;
        }
        verve_brain* loaded = nullptr;
        if (verve_brain_load_memory(bytes.data(), size, &loaded) != VERVE_OK) {
            failure = "round " + std::to_string(round) + ": " + lastError();
        }
        verve_brain_destroy(loaded);
        ++delivered;
    }
    stop = true;
    learner.join();
    EXPECT_EQ(failure, "");
    EXPECT_GT(delivered, 0);
    EXPECT_GT(updates.load(), 0);
    EXPECT_EQ(learnerError.load(), VERVE_OK);
    verve_agent_destroy(body);
    verve_brain_destroy(brain);
}

// Two threads hammer one agent: every call either runs alone or is refused, so the steps the
// agent counts are exactly the updates that succeeded.
TEST(Threads, OneAgentFromTwoThreadsIsRefusedNeverCorrupted) {
    verve_agent* agent = createOrFail(mixedDesc(true, 7));
    std::atomic<uint64_t> ok{0}, refused{0}, other{0};
    std::atomic<bool> badMessage{false};
    auto hammer = [&](int offset) {
        for (int i = 0; i < 3000; ++i) {
            uint32_t action = 0;
            const verve_result r = step(agent, i + offset, &action);
            if (r == VERVE_OK) ++ok;
            else if (r == VERVE_ERROR_INVALID_STATE) {
                ++refused;
                if (std::string(verve_last_error()).find("in use") == std::string::npos) badMessage = true;
            } else {
                ++other;
            }
        }
    };
    std::thread a(hammer, 0), b(hammer, 5000);
    a.join();
    b.join();
    verve_agent_stats stats{};
    stats.struct_size = sizeof stats;
    ASSERT_EQ(verve_agent_get_stats(agent, &stats), VERVE_OK) << lastError();
    EXPECT_EQ(other.load(), 0u);
    EXPECT_FALSE(badMessage.load());
    EXPECT_EQ(stats.steps, ok.load());
    EXPECT_EQ(ok.load() + refused.load(), 6000u);
    verve_agent_destroy(agent);
}

// Read-only calls share the agent's scratch memory: concurrent ones are refused the same way,
// and a call that runs gives the exact image.
TEST(Threads, ConcurrentSampleValuesAreExactOrRefused) {
    verve_agent* agent = createOrFail(mixedDesc(false, 3));
    uint32_t action = 0;
    for (int i = 0; i < 400; ++i) ASSERT_EQ(step(agent, i, &action), VERVE_OK);
    const verve_value_axis axes[2] = {{VERVE_SENSOR_CONTINUOUS, 0, 16}, {VERVE_SENSOR_CONTINUOUS, 1, 16}};
    const int32_t disc = 1;
    const float base[2] = {0.0f, 0.0f};
    std::vector<float> reference(256);
    ASSERT_EQ(verve_agent_sample_values(agent, axes, 2, &disc, 1, base, 2, reference.data(), 256), VERVE_OK);
    std::atomic<uint64_t> wrong{0}, other{0};
    auto sample = [&] {
        std::vector<float> image(256);
        for (int i = 0; i < 400; ++i) {
            const verve_result r = verve_agent_sample_values(agent, axes, 2, &disc, 1, base, 2, image.data(), 256);
            if (r == VERVE_OK) wrong += image != reference;
            else if (r != VERVE_ERROR_INVALID_STATE) ++other;
        }
    };
    std::thread a(sample), b(sample);
    a.join();
    b.join();
    EXPECT_EQ(wrong.load(), 0u);
    EXPECT_EQ(other.load(), 0u);
    verve_agent_destroy(agent);
}

}  // namespace
}  // namespace verve::hardening
