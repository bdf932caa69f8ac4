// Allocation failure in crowds (issue 32): the allocation-failure sweep of
// allocation_failure_test.cpp over a brain and its bodies, and over batches with workers, on
// Verve's own pool (whose threads start inside the first update) and on a host's job system.
// Every N-th allocation fails in turn; the host must never be taken down (std::terminate), the
// failing call must say VERVE_ERROR_OUT_OF_MEMORY, and what it reports as not done must be
// unchanged. Run under ASan by scripts/sanitize.sh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "hardening_support.hpp"
#include "memory_hooks.hpp"

namespace verve::hardening {
namespace {

std::string brainBytes(const verve_brain* brain) {
    size_t size = 0;
    EXPECT_EQ(verve_brain_save_memory_binary(brain, nullptr, &size), VERVE_OK) << lastError();
    std::string bytes(size, '\0');
    EXPECT_EQ(verve_brain_save_memory_binary(brain, &bytes[0], &size), VERVE_OK) << lastError();
    bytes.resize(size);
    return bytes;
}

// ---- a brain and its bodies ----------------------------------------------------------------

// Create a brain, three bodies, 60 updates through them in turn (RBFs grow, plans, an episode
// end), a brain save (size query, then the bytes, XML and binary) and a load of it.
class BrainScenario {
public:
    ~BrainScenario() {
        for (verve_agent* b : bodies_) verve_agent_destroy(b);
        verve_brain_destroy(brain_);
    }
    int calls() const { return 4 + 60 + 5; }

    verve_result call(int i) {
        if (i == 0) return verve_brain_create(&desc_, &brain_);
        if (i <= 3) {
            verve_agent* body = nullptr;
            const verve_result r = verve_brain_create_body(brain_, &body);
            if (r == VERVE_OK) bodies_.push_back(body);
            return r;
        }
        if (i < 64) {
            const int k = i - 4;
            verve_agent* body = bodies_[static_cast<std::size_t>(k % 3)];
            if (k == 30) return verve_agent_end_episode(body, 1.0f);
            const int32_t disc = k % 3;
            const float c[2] = {std::sin(0.9f * static_cast<float>(k)), std::cos(0.4f * static_cast<float>(k))};
            uint32_t action = 0;
            return verve_agent_update(body, k % 7 == 0 ? 1.0f : -0.1f, &disc, 1, c, 2, 0.1f, &action);
        }
        const bool xml = i < 66;
        if (i == 64 || i == 66) {
            size_ = 0;
            return (xml ? verve_brain_save_memory : verve_brain_save_memory_binary)(brain_, nullptr, &size_);
        }
        if (i == 65 || i == 67) {
            saved_.assign(size_, '\0');
            return (xml ? verve_brain_save_memory : verve_brain_save_memory_binary)(brain_, &saved_[0], &size_);
        }
        verve_brain* loaded = nullptr;
        const verve_result r = verve_brain_load_memory(saved_.data(), size_, &loaded);
        if (r == VERVE_OK) verve_brain_destroy(loaded);
        else if (loaded != nullptr) return VERVE_ERROR_INTERNAL;  // a failed load hands out nothing
        return r;
    }

    // The brain's save and every body's (the brain plus its short-term memory).
    std::string state() const {
        if (brain_ == nullptr) return {};
        std::string s = brainBytes(brain_);
        for (const verve_agent* b : bodies_) s += saveToString(b);
        return s;
    }

private:
    verve_agent_desc desc_ = mixedDesc(true, 5);
    verve_brain* brain_ = nullptr;
    std::vector<verve_agent*> bodies_;
    size_t size_ = 0;
    std::string saved_;
};

TEST(AllocationFailure, EveryFailedAllocationLeavesTheBrainAndItsBodiesAsTheyWere) {
    CountingAllocator allocator;
    const verve_hooks hooks = allocator.hooks();
    ASSERT_EQ(verve_set_hooks(&hooks), VERVE_OK) << lastError();
    std::string reference;
    std::vector<long> upTo;
    {
        BrainScenario s;
        for (int i = 0; i < s.calls(); ++i) {
            ASSERT_EQ(s.call(i), VERVE_OK) << "call " << i << ": " << lastError();
            upTo.push_back(allocator.allocations.load());
        }
        reference = uncounted(allocator, [&] { return s.state(); });
    }
    const long total = upTo.back();
    ASSERT_GT(total, 200);
    RecordProperty("allocations", static_cast<int>(total));
    int failures = 0;
    for (long n = 1; n <= total; ++n) {
        allocator.allocations = 0;
        allocator.failAt = n;
        BrainScenario s;
        bool failed = false;
        int failedIn = -1;
        for (int i = 0; i < s.calls(); ++i) {
            const bool hit = !failed && n <= upTo[static_cast<std::size_t>(i)];
            const std::string before = hit ? uncounted(allocator, [&] { return s.state(); }) : std::string();
            const verve_result r = s.call(i);
            if (!hit) {
                ASSERT_EQ(r, VERVE_OK) << "N=" << n << " call " << i << ": " << lastError();
                continue;
            }
            ASSERT_EQ(r, VERVE_ERROR_OUT_OF_MEMORY) << "N=" << n << " call " << i << ": " << lastError();
            ASSERT_TRUE(uncounted(allocator, [&] { return s.state(); }) == before) << "N=" << n << " call " << i << " changed the brain";
            failed = true;
            failedIn = i;
            ++failures;
            allocator.failAt = -1;
            ASSERT_EQ(s.call(i), VERVE_OK) << "N=" << n << " retrying call " << i << ": " << lastError();
        }
        ASSERT_TRUE(failed) << "allocation " << n << " never happened";
        ASSERT_TRUE(uncounted(allocator, [&] { return s.state(); }) == reference)
            << "N=" << n << " (failed in call " << failedIn << "): the retried scenario ends elsewhere";
    }
    EXPECT_EQ(failures, total);
    ASSERT_EQ(verve_set_hooks(nullptr), VERVE_OK) << lastError();
}

// Issue 32: verve_brain_destroy checks the in-use flag as verve_agent_destroy does. The host's
// allocator, called inside a brain save, plays another thread destroying the brain meanwhile.
struct Destroyer {
    CountingAllocator counting;
    verve_brain* brain = nullptr;
    bool armed = false, tried = false;
    std::string error;
    static void* VERVE_CALL allocate(void* user, size_t size) {
        auto* self = static_cast<Destroyer*>(user);
        if (self->armed) {
            self->armed = false;
            self->tried = true;
            verve_brain_destroy(self->brain);
            self->error = verve_last_error();
        }
        return CountingAllocator::allocate(&self->counting, size);
    }
    static void VERVE_CALL release(void* user, void* block) { CountingAllocator::release(&static_cast<Destroyer*>(user)->counting, block); }
};

TEST(AllocationFailure, DestroyingABrainInsideOneOfItsCallsIsRefused) {
    Destroyer d;
    verve_hooks hooks{};
    hooks.struct_size = VERVE_HOOKS_SIZE_V1;
    hooks.malloc_fn = &Destroyer::allocate;
    hooks.free_fn = &Destroyer::release;
    hooks.alloc_user = &d;
    ASSERT_EQ(verve_set_hooks(&hooks), VERVE_OK) << lastError();
    const verve_agent_desc desc = mixedDesc(false, 3);
    ASSERT_EQ(verve_brain_create(&desc, &d.brain), VERVE_OK) << lastError();
    size_t size = 0;
    d.armed = true;
    ASSERT_EQ(verve_brain_save_memory(d.brain, nullptr, &size), VERVE_OK) << lastError();
    ASSERT_TRUE(d.tried);
    EXPECT_NE(d.error.find("not destroyed"), std::string::npos) << d.error;
    uint32_t count = 0;
    EXPECT_EQ(verve_brain_get_rbf_count(d.brain, &count), VERVE_OK) << "the brain survived";
    verve_brain_destroy(d.brain);
    ASSERT_EQ(verve_set_hooks(nullptr), VERVE_OK) << lastError();
}

// Issue 32: a file save holds the brain's flag only while it serialises; the disk write comes
// after, so a body's update meanwhile is let in (it was refused for the whole write before). The
// host's allocator, called throughout the save (the write's paths and names allocate too), plays
// the game's other thread updating a body at every moment of it.
struct Updater {
    CountingAllocator counting;
    verve_agent* body = nullptr;
    bool armed = false, inside = false;
    int refused = 0, updated = 0;
    static void* VERVE_CALL allocate(void* user, size_t size) {
        auto* self = static_cast<Updater*>(user);
        if (self->armed && !self->inside) {
            self->inside = true;
            const float c[2] = {0.3f, -0.2f};
            const int32_t disc = 1;
            uint32_t action = 0;
            const verve_result r = verve_agent_update(self->body, 0.0f, &disc, 1, c, 2, 0.1f, &action);
            (r == VERVE_OK ? self->updated : self->refused) += 1;
            self->inside = false;
        }
        return CountingAllocator::allocate(&self->counting, size);
    }
    static void VERVE_CALL release(void* user, void* block) { CountingAllocator::release(&static_cast<Updater*>(user)->counting, block); }
};

TEST(AllocationFailure, ABodyUpdatesWhileItsBrainSaveWritesTheFile) {
    Updater u;
    verve_hooks hooks{};
    hooks.struct_size = VERVE_HOOKS_SIZE_V1;
    hooks.malloc_fn = &Updater::allocate;
    hooks.free_fn = &Updater::release;
    hooks.alloc_user = &u;
    ASSERT_EQ(verve_set_hooks(&hooks), VERVE_OK) << lastError();
    const verve_agent_desc desc = mixedDesc(false, 3);
    verve_brain* brain = nullptr;
    ASSERT_EQ(verve_brain_create(&desc, &brain), VERVE_OK) << lastError();
    ASSERT_EQ(verve_brain_create_body(brain, &u.body), VERVE_OK) << lastError();
    const std::string path = ::testing::TempDir() + "verve_brain_autosave.xml";
    u.armed = true;
    ASSERT_EQ(verve_brain_save(brain, path.c_str()), VERVE_OK) << lastError();
    u.armed = false;
    EXPECT_GT(u.refused, 0) << "no allocation while serialising?";
    EXPECT_GT(u.updated, 0) << "every update during the save was refused: the disk write held the brain's flag";
    RecordProperty("updatesRefused", u.refused);
    RecordProperty("updatesLetIn", u.updated);
    verve_brain* loaded = nullptr;
    ASSERT_EQ(verve_brain_load(path.c_str(), &loaded), VERVE_OK) << lastError();
    verve_brain_destroy(loaded);
    std::remove(path.c_str());
    verve_agent_destroy(u.body);
    verve_brain_destroy(brain);
    ASSERT_EQ(verve_set_hooks(nullptr), VERVE_OK) << lastError();
}

// ---- batches with workers ------------------------------------------------------------------

// A host job system: a task's ranges go round-robin to threads started at enqueue, joined at finish.
struct HostTask {
    std::vector<std::thread> threads;
};
void* VERVE_CALL enqueueOnThreads(verve_task_fn task, uint32_t count, uint32_t minRange, void* taskContext, void*) {
    constexpr uint32_t workers = 4;
    const uint32_t range = std::max(std::max(minRange, 1u), (count + workers - 1) / workers);
    auto* job = new HostTask;
    for (uint32_t w = 0; w < workers; ++w) {
        job->threads.emplace_back([=] {
            for (uint32_t begin = w * range; begin < count; begin += workers * range) {
                task(begin, std::min(count, begin + range), w, taskContext);
            }
        });
    }
    return job;
}
void VERVE_CALL finishOnThreads(void* userTask, void*) {
    auto* job = static_cast<HostTask*>(userTask);
    for (auto& t : job->threads) t.join();
    delete job;
}

constexpr uint32_t kCrowd = 8;  // 4 agents of their own, then 4 bodies of one brain

// Creates the crowd and a 4-worker batch, then 9 batch updates: the first starts the batch's own
// pool (its threads); the agents grow RBFs and plan in every one; the brain does not plan, and its
// bodies see two observations in turn, so that after the first two updates they run in the batch's
// phases (docs/crowds.md), but for the steps where some are shown what to do.
class BatchScenario {
public:
    explicit BatchScenario(bool hostJobs) : hostJobs_(hostJobs) {}
    ~BatchScenario() {
        verve_batch_destroy(batch_);
        for (verve_agent* a : agents_) verve_agent_destroy(a);
        verve_brain_destroy(brain_);
    }
    int calls() const { return 4 + 1 + 4 + 1 + 9; }
    static bool isBatchUpdate(int i) { return i >= 10; }

    verve_result call(int i) {
        verve_agent* made = nullptr;
        verve_result r = VERVE_OK;
        if (i < 4) {
            const verve_agent_desc d = mixedDesc(true, 20 + static_cast<uint64_t>(i));
            r = verve_agent_create(&d, &made);
        } else if (i == 4) {
            verve_agent_desc d = mixedDesc(false, 30);
            d.num_continuous_actions = 1;  // the bodies are shown continuous actions too
            return verve_brain_create(&d, &brain_);
        } else if (i < 9) {
            r = verve_brain_create_body(brain_, &made);
        } else if (i == 9) {
            verve_batch_desc d;
            verve_batch_desc_default(&d);
            d.worker_count = 4;
            if (hostJobs_) {
                d.enqueue_task = enqueueOnThreads;
                d.finish_task = finishOnThreads;
            }
            return verve_batch_create(&d, &batch_);
        } else {
            const int k = i - 10;
            float rewards[kCrowd];
            int32_t discrete[kCrowd];
            float continuous[2 * kCrowd];
            for (uint32_t a = 0; a < kCrowd; ++a) {
                const float t = static_cast<float>((a < 4 ? k : k % 2) * 11 + static_cast<int>(a));
                rewards[a] = (k + static_cast<int>(a)) % 4 == 0 ? 1.0f : -0.1f;
                discrete[a] = static_cast<int32_t>(((a < 4 ? k : k % 2) + a) % 3);
                continuous[2 * a] = std::sin(0.9f * t);
                continuous[2 * a + 1] = std::cos(0.4f * t);
            }
            uint32_t actions[kCrowd];
            for (auto& res : results) res = VERVE_ERROR_INTERNAL;
            if (k % 3 == 2) {  // every third step, some agents are shown what to do
                uint32_t demonstrated[kCrowd];
                for (uint32_t a = 0; a < kCrowd; ++a) demonstrated[a] = a % 2 == 0 ? (k + a) % 3 : VERVE_AGENT_CHOOSES;
                if (k % 2 == 0) {
                    return verve_batch_update_demonstrated(batch_, agents_.data(), kCrowd, rewards, discrete, nullptr,
                                                           kCrowd, continuous, nullptr, 2 * kCrowd, 0.1f, demonstrated,
                                                           actions, results);
                }
                const float shown[4] = {0.5f, -0.25f, 0.75f, -1.0f};  // one per body: the agents have none
                return verve_batch_update_demonstrated_continuous(batch_, agents_.data(), kCrowd, rewards, discrete,
                                                                  nullptr, kCrowd, continuous, nullptr, 2 * kCrowd, 0.1f,
                                                                  demonstrated, shown, nullptr, 4, actions, results);
            }
            return verve_batch_update(batch_, agents_.data(), kCrowd, rewards, discrete, nullptr, kCrowd, continuous,
                                      nullptr, 2 * kCrowd, 0.1f, actions, results);
        }
        if (r == VERVE_OK) agents_.push_back(made);
        return r;
    }

    std::vector<std::string> states() const {
        std::vector<std::string> s;
        for (const verve_agent* a : agents_) s.push_back(saveToString(a));
        return s;
    }

    verve_result results[kCrowd] = {};

private:
    bool hostJobs_;
    std::vector<verve_agent*> agents_;
    verve_brain* brain_ = nullptr;
    verve_batch* batch_ = nullptr;
};

class BatchAllocationFailure : public ::testing::TestWithParam<bool> {};

TEST_P(BatchAllocationFailure, NeverTakesTheHostDownAndReportsWhatItDidNotDo) {
    CountingAllocator allocator;
    const verve_hooks hooks = allocator.hooks();
    ASSERT_EQ(verve_set_hooks(&hooks), VERVE_OK) << lastError();
    std::vector<long> upTo;
    {
        BatchScenario s(GetParam());
        for (int i = 0; i < s.calls(); ++i) {
            ASSERT_EQ(s.call(i), VERVE_OK) << "call " << i << ": " << lastError();
            upTo.push_back(allocator.allocations.load());
        }
    }
    const long total = upTo.back();
    ASSERT_GT(total, 200);
    RecordProperty("allocations", static_cast<int>(total));
    int inBatches = 0;
    for (long n = 1; n <= total; ++n) {
        allocator.allocations = 0;
        allocator.failAt = n;
        BatchScenario s(GetParam());
        bool failed = false;
        for (int i = 0; i < s.calls(); ++i) {
            const bool hit = !failed && n <= upTo[static_cast<std::size_t>(i)];
            const std::vector<std::string> before = hit ? [&] {
                const long failAt = allocator.failAt.exchange(-1);
                const long count = allocator.allocations.load();
                auto st = s.states();
                allocator.allocations = count;
                allocator.failAt = failAt;
                return st;
            }() : std::vector<std::string>();
            const verve_result r = s.call(i);
            if (!hit) {
                ASSERT_EQ(r, VERVE_OK) << "N=" << n << " call " << i << ": " << lastError();
                continue;
            }
            ASSERT_EQ(r, VERVE_ERROR_OUT_OF_MEMORY) << "N=" << n << " call " << i << ": " << lastError();
            failed = true;
            allocator.failAt = -1;
            if (!BatchScenario::isBatchUpdate(i)) {
                ASSERT_EQ(s.call(i), VERVE_OK) << "N=" << n << " retrying call " << i << ": " << lastError();
                continue;
            }
            ++inBatches;
            // Each agent's verdict: VERVE_OK (updated) or out of memory (left as it was).
            const std::vector<std::string> after = s.states();
            int notDone = 0;
            // A body's save holds its brain's weights, which its brain's other bodies change: it is
            // compared only when none of them was updated either.
            bool bodiesUpdated = false;
            for (uint32_t a = 4; a < kCrowd; ++a) bodiesUpdated = bodiesUpdated || s.results[a] == VERVE_OK;
            for (uint32_t a = 0; a < kCrowd; ++a) {
                ASSERT_TRUE(s.results[a] == VERVE_OK || s.results[a] == VERVE_ERROR_OUT_OF_MEMORY)
                    << "N=" << n << " agent " << a << ": " << verve_result_name(s.results[a]);
                if (s.results[a] == VERVE_OK) continue;
                ++notDone;
                if (a >= 4 && bodiesUpdated) continue;
                ASSERT_TRUE(after[a] == before[a]) << "N=" << n << " call " << i << " changed agent " << a
                                                   << ", reported as not updated";
            }
            ASSERT_GT(notDone, 0) << "N=" << n << ": out of memory, yet every agent reported as updated";
        }
        ASSERT_TRUE(failed) << "allocation " << n << " never happened";
    }
    RecordProperty("failuresInBatchUpdates", inBatches);
    EXPECT_GT(inBatches, 0);
    ASSERT_EQ(verve_set_hooks(nullptr), VERVE_OK) << lastError();
}

INSTANTIATE_TEST_SUITE_P(OwnPoolAndHostJobs, BatchAllocationFailure, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& p) { return p.param ? "HostJobs" : "OwnPool"; });

}  // namespace
}  // namespace verve::hardening
