// Many agents through the C ABI: verve_batch_update gives separate agents exactly the results of
// updating each in array order, and the bodies of a brain the results of its phases (docs/crowds.md),
// the same for 1, 2, 3 and 8 threads of Verve's pool and on a host's job system; bodies of one
// brain share what they learn; bad input anywhere refuses the whole call.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "crowd_support.hpp"
#include "verve_c.h"

namespace {

using verve_crowd_test::makeBatch;
using verve_crowd_test::saved;

verve_agent_desc shape(uint32_t discreteValues, uint32_t continuous, uint32_t resolution, uint32_t actions,
                       uint64_t seed, bool planning = false) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_discrete_sensors = discreteValues > 0 ? 1 : 0;
    d.discrete_sensor_values[0] = discreteValues;
    d.num_continuous_sensors = continuous;
    d.continuous_sensor_circular[0] = 1;
    d.resolution = resolution;
    d.num_actions = actions;
    d.seed = seed;
    d.planning = planning ? 1 : 0;
    return d;
}

// A crowd of mixed shapes, 8 times over: separate agents, the bodies of two brains interleaved
// with them, and one agent listed twice. Every crowd built alike is identical.
struct Crowd {
    std::vector<verve_brain*> brains;
    std::vector<verve_agent*> owned;  // each agent once, to destroy
    std::vector<verve_agent*> items;  // the batch's order
    std::vector<bool> ownedBody, itemBody;  // which are bodies of a brain

    Crowd() {
        for (uint64_t copy = 0; copy < 8; ++copy) add(10 * copy);
    }
    void add(uint64_t seed) {
        // `many`: six sensors in groups, whose rates the bodies learn too (VERVE_ADAPT_GROUP_RATES).
        const verve_agent_desc tiny = shape(0, 2, 8, 2, seed + 1), grid = shape(10, 0, 10, 5, seed + 2),
                               planner = shape(5, 1, 10, 3, seed + 3, true), cart = shape(0, 4, 4, 3, seed + 4),
                               many = shape(0, 6, 5, 3, seed + 5);
        const std::size_t first = brains.size();
        for (const auto& d : {tiny, cart, many}) {
            verve_brain* b = nullptr;
            EXPECT_EQ(verve_brain_create(&d, &b), VERVE_OK) << verve_last_error();
            brains.push_back(b);
        }
        auto agent = [&](const verve_agent_desc& d) {
            verve_agent* a = nullptr;
            EXPECT_EQ(verve_agent_create(&d, &a), VERVE_OK) << verve_last_error();
            owned.push_back(a);
            ownedBody.push_back(false);
            return a;
        };
        auto body = [&](std::size_t brain) {
            verve_agent* a = nullptr;
            EXPECT_EQ(verve_brain_create_body(brains[first + brain], &a), VERVE_OK) << verve_last_error();
            owned.push_back(a);
            ownedBody.push_back(true);
            return a;
        };
        verve_agent* twice = agent(tiny);
        for (verve_agent* a : {twice, body(0), agent(grid), body(0), agent(planner), body(1), body(2), body(0), agent(tiny),
                               body(1), body(2), body(0), body(1), body(0), agent(grid), body(2), twice}) {
            items.push_back(a);
            itemBody.push_back(ownedBody[static_cast<std::size_t>(std::find(owned.begin(), owned.end(), a) - owned.begin())]);
        }
    }
    ~Crowd() {
        for (auto* a : owned) verve_agent_destroy(a);
        for (auto* b : brains) verve_brain_destroy(b);
    }
};

// Packed observations of a step: each agent's values back to back; a small world per item where
// the action moves a point around, so actions feed back into what the agents see next.
struct Inputs {
    std::vector<float> rewards, continuous;
    std::vector<int32_t> discrete;
};

Inputs inputsFor(const Crowd& crowd, int step, const std::vector<uint32_t>& actions) {
    Inputs in;
    for (std::size_t i = 0; i < crowd.items.size(); ++i) {
        verve_agent_desc d;
        verve_agent_desc_init(&d, sizeof d);
        verve_agent_get_desc(crowd.items[i], &d);
        const float phase = 0.37f * static_cast<float>(step) + 0.9f * static_cast<float>(i) + 0.5f * static_cast<float>(actions[i]);
        if (d.num_discrete_sensors == 1) in.discrete.push_back((step + static_cast<int>(i + actions[i])) % static_cast<int>(d.discrete_sensor_values[0]));
        for (uint32_t c = 0; c < d.num_continuous_sensors; ++c) in.continuous.push_back(std::sin(phase + static_cast<float>(c)));
        in.rewards.push_back(actions[i] == i % d.num_actions ? 0.5f : -0.1f);
    }
    return in;
}

using Updater = std::function<void(const Crowd&, const Inputs&, std::vector<uint32_t>&)>;

// Every action taken and the final saves of a run; `bodies` false keeps only the separate agents'.
struct Outcome {
    std::vector<uint32_t> actions;
    std::vector<std::string> saves;
    std::vector<bool> actionOfBody, saveOfBody;
    Outcome only(bool bodies) const {
        Outcome r;
        for (std::size_t i = 0; i < actions.size(); ++i) {
            if (bodies || !actionOfBody[i]) r.actions.push_back(actions[i]);
        }
        for (std::size_t i = 0; i < saves.size(); ++i) {
            if (bodies || !saveOfBody[i]) r.saves.push_back(saves[i]);
        }
        return r;
    }
};

// Runs a crowd for 120 steps with trial ends.
Outcome run(const Updater& update) {
    Crowd crowd;
    std::vector<uint32_t> actions(crowd.items.size(), 0), history;
    for (int step = 0; step < 120; ++step) {
        update(crowd, inputsFor(crowd, step, actions), actions);
        history.insert(history.end(), actions.begin(), actions.end());
        if (step % 40 == 39) {
            for (auto* a : crowd.owned) EXPECT_EQ(verve_agent_end_episode(a, 1.0f), VERVE_OK);
        }
    }
    Outcome r;
    r.actions = history;
    for (auto* a : crowd.owned) r.saves.push_back(saved(a));
    for (int step = 0; step < 120; ++step) r.actionOfBody.insert(r.actionOfBody.end(), crowd.itemBody.begin(), crowd.itemBody.end());
    r.saveOfBody = crowd.ownedBody;
    return r;
}

void sequential(const Crowd& crowd, const Inputs& in, std::vector<uint32_t>& actions) {
    std::size_t d = 0, c = 0;
    for (std::size_t i = 0; i < crowd.items.size(); ++i) {
        verve_agent_desc desc;
        verve_agent_desc_init(&desc, sizeof desc);
        verve_agent_get_desc(crowd.items[i], &desc);
        ASSERT_EQ(verve_agent_update(crowd.items[i], in.rewards[i], in.discrete.data() + d, desc.num_discrete_sensors,
                                     in.continuous.data() + c, desc.num_continuous_sensors, 0.1f, &actions[i]),
                  VERVE_OK)
            << verve_last_error();
        d += desc.num_discrete_sensors;
        c += desc.num_continuous_sensors;
    }
}

Updater batched(verve_batch* batch) {
    return [batch](const Crowd& crowd, const Inputs& in, std::vector<uint32_t>& actions) {
        std::vector<verve_result> results(crowd.items.size(), VERVE_ERROR_INTERNAL);
        ASSERT_EQ(verve_batch_update(batch, crowd.items.data(), static_cast<uint32_t>(crowd.items.size()), in.rewards.data(),
                                     in.discrete.data(), nullptr, static_cast<uint32_t>(in.discrete.size()),
                                     in.continuous.data(), nullptr, static_cast<uint32_t>(in.continuous.size()), 0.1f,
                                     actions.data(), results.data()),
                  VERVE_OK)
            << verve_last_error();
        for (auto r : results) ASSERT_EQ(r, VERVE_OK);
    };
}

// Separate agents: the results of single calls in array order. Bodies of a brain: those of the
// batch's phases, the same for any number of threads.
TEST(Batch, SameResultsForAnyThreadCount) {
    const Outcome single = run(sequential);
    verve_batch* one = makeBatch(1);
    const Outcome expected = run(batched(one));
    verve_batch_destroy(one);
    EXPECT_EQ(expected.only(false).actions, single.only(false).actions) << "separate agents: other actions than single calls";
    EXPECT_EQ(expected.only(false).saves, single.only(false).saves) << "separate agents: other agents than after single calls";
    EXPECT_NE(expected.actions, single.actions) << "the bodies were updated as single calls: no phases ran";
    for (uint32_t workers : {1u, 2u, 3u, 8u}) {
        verve_batch* batch = makeBatch(workers);
        uint32_t count = 0;
        ASSERT_EQ(verve_batch_get_worker_count(batch, &count), VERVE_OK);
        EXPECT_EQ(count, workers);
        const Outcome got = run(batched(batch));
        EXPECT_EQ(got.actions, expected.actions) << workers << " workers: different actions";
        EXPECT_EQ(got.saves, expected.saves) << workers << " workers: different agents afterwards";
        verve_batch_destroy(batch);
    }
}

// A host job system: each task's ranges (at least min_range items) go round-robin to real threads
// that start at enqueue and are joined at finish.
struct HostJobs {
    uint32_t workers = 3;
    std::atomic<int> tasks{0}, ranges{0};
    std::atomic<bool> badWorker{false};
};

struct HostTask {
    std::vector<std::thread> threads;
};

void* VERVE_CALL enqueueOnThreads(verve_task_fn task, uint32_t count, uint32_t minRange, void* taskContext, void* user) {
    auto* host = static_cast<HostJobs*>(user);
    ++host->tasks;
    const uint32_t range = std::max(std::max(minRange, 1u), (count + host->workers - 1) / host->workers);
    auto* job = new HostTask;
    for (uint32_t w = 0; w < host->workers; ++w) {
        job->threads.emplace_back([=] {
            for (uint32_t begin = w * range; begin < count; begin += host->workers * range) {
                ++host->ranges;
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

// A host that runs a task at once on the calling thread and says so by returning NULL.
void* VERVE_CALL enqueueInline(verve_task_fn task, uint32_t count, uint32_t, void* taskContext, void* user) {
    ++static_cast<HostJobs*>(user)->tasks;
    task(0, count, 0, taskContext);
    return nullptr;
}

void VERVE_CALL finishNever(void*, void* user) { static_cast<HostJobs*>(user)->badWorker = true; }

TEST(Batch, SameResultsOnAHostJobSystem) {
    verve_batch* own = makeBatch(2);
    const Outcome expected = run(batched(own));
    verve_batch_destroy(own);
    for (bool threaded : {true, false}) {
        HostJobs host;
        verve_batch_desc d;
        verve_batch_desc_default(&d);
        d.worker_count = host.workers;
        d.enqueue_task = threaded ? enqueueOnThreads : enqueueInline;
        d.finish_task = threaded ? finishOnThreads : finishNever;
        d.user_context = &host;
        verve_batch* batch = nullptr;
        ASSERT_EQ(verve_batch_create(&d, &batch), VERVE_OK) << verve_last_error();
        const Outcome got = run(batched(batch));
        EXPECT_EQ(got.actions, expected.actions);
        EXPECT_EQ(got.saves, expected.saves);
        // Separate agents in one task; bodies of brains in three more (docs/crowds.md).
        EXPECT_EQ(host.tasks.load(), 4 * 120) << "four tasks per batch update";
        if (threaded) {
            EXPECT_GE(host.ranges.load(), 2 * 120) << "the host's threads shared the work";
        }
        EXPECT_FALSE(host.badWorker.load()) << "finish_task called for a task that ran inline";
        verve_batch_destroy(batch);
    }
}

// A crowd whose arrays outgrow the caches (300 cart-pole-shaped agents of ~700 RBFs, ~10 MB) takes
// the batch's other path: each update asks for the next agent's arrays from inside its loops. The
// same actions and agents as single updates, and single updates afterwards still match.
TEST(Batch, SameResultsForACrowdLargerThanTheCaches) {
    const verve_agent_desc d = shape(0, 4, 8, 3, 21);
    verve_agent* grown = nullptr;
    ASSERT_EQ(verve_agent_create(&d, &grown), VERVE_OK);
    uint32_t action = 0, rbfs = 0;
    for (float t = 0.0f; rbfs < 700; t += 1.0f) {
        const float x[4] = {std::sin(0.05f * t), std::cos(0.031f * t), std::sin(0.017f * t + 1), std::cos(0.043f * t + 2)};
        ASSERT_EQ(verve_agent_update(grown, action == 0 ? 0.1f : -0.1f, nullptr, 0, x, 4, 0.1f, &action), VERVE_OK);
        ASSERT_EQ(verve_agent_get_rbf_count(grown, &rbfs), VERVE_OK);
    }
    const std::string xml = saved(grown);
    verve_agent_destroy(grown);
    constexpr uint32_t kAgents = 300;
    std::vector<verve_agent*> batchAgents(kAgents), singleAgents(kAgents);
    for (auto* set : {&batchAgents, &singleAgents}) {
        for (auto*& a : *set) ASSERT_EQ(verve_agent_load_memory(xml.data(), xml.size(), &a), VERVE_OK);
    }
    verve_batch* batch = makeBatch(2);
    std::vector<uint32_t> batchActions(kAgents, 0), singleActions(kAgents, 0);
    std::vector<float> rewards(kAgents), sensors(4 * kAgents);
    for (int step = 0; step < 30; ++step) {
        for (uint32_t i = 0; i < kAgents; ++i) {
            rewards[i] = batchActions[i] == i % 3 ? 0.5f : -0.1f;
            for (uint32_t c = 0; c < 4; ++c) {
                sensors[4 * i + c] = std::sin(0.3f * static_cast<float>(step) + 0.7f * static_cast<float>(i) + 1.3f * static_cast<float>(c));
            }
        }
        ASSERT_EQ(verve_batch_update(batch, batchAgents.data(), kAgents, rewards.data(), nullptr, nullptr, 0,
                                     sensors.data(), nullptr, 4 * kAgents, 0.1f, batchActions.data(), nullptr),
                  VERVE_OK)
            << verve_last_error();
        for (uint32_t i = 0; i < kAgents; ++i) {
            ASSERT_EQ(verve_agent_update(singleAgents[i], rewards[i], nullptr, 0, &sensors[4 * i], 4, 0.1f, &singleActions[i]), VERVE_OK);
        }
        ASSERT_EQ(batchActions, singleActions) << "step " << step;
    }
    for (uint32_t i = 0; i < kAgents; ++i) {  // a single update after the batch's
        const float x[4] = {0.1f, -0.2f, 0.3f, -0.4f};
        uint32_t a = 0, b = 0;
        ASSERT_EQ(verve_agent_update(batchAgents[i], 0.2f, nullptr, 0, x, 4, 0.1f, &a), VERVE_OK);
        ASSERT_EQ(verve_agent_update(singleAgents[i], 0.2f, nullptr, 0, x, 4, 0.1f, &b), VERVE_OK);
        ASSERT_EQ(a, b);
        if (i % 50 == 0) {
            EXPECT_EQ(saved(batchAgents[i]), saved(singleAgents[i])) << "agent " << i;
        }
    }
    verve_batch_destroy(batch);
    for (auto* set : {&batchAgents, &singleAgents}) {
        for (auto* a : *set) verve_agent_destroy(a);
    }
}

TEST(Batch, OffsetsReadTheSameValuesAsPacking) {
    // Agent 0: 2 continuous, agent 1: 1 discrete; given at explicit, padded offsets.
    const verve_agent_desc a = shape(0, 2, 8, 2, 5), b = shape(10, 0, 10, 5, 6);
    verve_agent *p[2], *q[2];
    for (auto* set : {p, q}) {
        ASSERT_EQ(verve_agent_create(&a, &set[0]), VERVE_OK);
        ASSERT_EQ(verve_agent_create(&b, &set[1]), VERVE_OK);
    }
    verve_batch* batch = makeBatch(2);
    const float rewards[2] = {0.5f, -0.5f};
    const float packedC[2] = {0.25f, -0.5f}, spacedC[5] = {9, 9, 9, 0.25f, -0.5f};
    const int32_t packedD[1] = {7}, spacedD[3] = {-1, 7, -1};
    const uint32_t cOffsets[2] = {3, 0}, dOffsets[2] = {0, 1};  // agent 1 has no continuous values
    uint32_t actionsP[2], actionsQ[2];
    for (int s = 0; s < 20; ++s) {
        ASSERT_EQ(verve_batch_update(batch, p, 2, rewards, packedD, nullptr, 1, packedC, nullptr, 2, 0.1f, actionsP, nullptr), VERVE_OK)
            << verve_last_error();
        ASSERT_EQ(verve_batch_update(batch, q, 2, rewards, spacedD, dOffsets, 3, spacedC, cOffsets, 5, 0.1f, actionsQ, nullptr), VERVE_OK)
            << verve_last_error();
        EXPECT_EQ(actionsP[0], actionsQ[0]);
        EXPECT_EQ(actionsP[1], actionsQ[1]);
    }
    EXPECT_EQ(saved(p[0]), saved(q[0]));
    EXPECT_EQ(saved(p[1]), saved(q[1]));
    verve_batch_destroy(batch);
    for (auto* x : {p[0], p[1], q[0], q[1]}) verve_agent_destroy(x);
}

class BatchRefusal : public ::testing::Test {
protected:
    void SetUp() override {
        batch_ = makeBatch(2);
        const verve_agent_desc d = shape(4, 1, 8, 3, 9);
        for (auto*& a : agents_) ASSERT_EQ(verve_agent_create(&d, &a), VERVE_OK);
        for (int i = 0; i < 3; ++i) discrete_[i] = i;
        ASSERT_EQ(update(), VERVE_OK) << verve_last_error();
        for (auto* a : agents_) before_.push_back(saved(a));
    }
    void TearDown() override {
        for (auto* a : agents_) verve_agent_destroy(a);
        verve_batch_destroy(batch_);
    }
    verve_result update(float dt = 0.1f, const uint32_t* offsets = nullptr) {
        for (auto& a : actions_) a = 77;
        for (auto& r : results_) r = VERVE_ERROR_INTERNAL;
        return verve_batch_update(batch_, agents_, 3, rewards_, discrete_, nullptr, 3, continuous_, offsets, 3, dt,
                                  actions_, results_);
    }
    void expectUnchanged() {
        for (int i = 0; i < 3; ++i) EXPECT_EQ(saved(agents_[i]), before_[i]) << "agent " << i << " changed";
        for (auto a : actions_) EXPECT_EQ(a, 77u) << "actions written by a refused call";
    }
    verve_batch* batch_ = nullptr;
    verve_agent* agents_[3] = {};
    float rewards_[3] = {0.1f, 0.2f, 0.3f};
    int32_t discrete_[3] = {};
    float continuous_[3] = {0.1f, 0.2f, 0.3f};
    uint32_t actions_[3] = {};
    verve_result results_[3] = {};
    std::vector<std::string> before_;
};

TEST_F(BatchRefusal, ADemonstratedActionOutOfRangeRefusesTheWholeCall) {
    const uint32_t demonstrated[3] = {VERVE_AGENT_CHOOSES, 3, 0};  // 3 actions: 0..2
    for (auto& a : actions_) a = 77;
    EXPECT_EQ(verve_batch_update_demonstrated(batch_, agents_, 3, rewards_, discrete_, nullptr, 3, continuous_, nullptr, 3,
                                              0.1f, demonstrated, actions_, results_),
              VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(verve_last_error()).find("agents[1]"), std::string::npos) << verve_last_error();
    EXPECT_EQ(results_[0], VERVE_OK);
    EXPECT_EQ(results_[1], VERVE_ERROR_INVALID_ARGUMENT);
    expectUnchanged();
}

// Demonstrated steps in a batch are those of single calls in array order; the others choose.
TEST_F(BatchRefusal, DemonstratedStepsInABatchAreThoseOfSingleCalls) {
    const verve_agent_desc d = shape(4, 1, 8, 3, 9);
    verve_agent* twins[3] = {};
    for (int i = 0; i < 3; ++i) {
        ASSERT_EQ(verve_agent_create(&d, &twins[i]), VERVE_OK);
        uint32_t a = 0;
        ASSERT_EQ(verve_agent_update(twins[i], rewards_[i], &discrete_[i], 1, &continuous_[i], 1, 0.1f, &a), VERVE_OK);
    }
    for (int step = 0; step < 20; ++step) {
        const uint32_t demonstrated[3] = {VERVE_AGENT_CHOOSES, static_cast<uint32_t>(step % 3), 2};
        for (int i = 0; i < 3; ++i) continuous_[i] = 0.1f * static_cast<float>((step + i) % 10) - 0.5f;
        ASSERT_EQ(verve_batch_update_demonstrated(batch_, agents_, 3, rewards_, discrete_, nullptr, 3, continuous_, nullptr,
                                                  3, 0.1f, demonstrated, actions_, results_),
                  VERVE_OK)
            << verve_last_error();
        for (int i = 0; i < 3; ++i) {
            uint32_t a = 99;
            if (demonstrated[i] == VERVE_AGENT_CHOOSES) {
                ASSERT_EQ(verve_agent_update(twins[i], rewards_[i], &discrete_[i], 1, &continuous_[i], 1, 0.1f, &a), VERVE_OK);
            } else {
                ASSERT_EQ(verve_agent_update_demonstrated(twins[i], rewards_[i], &discrete_[i], 1, &continuous_[i], 1, 0.1f,
                                                          nullptr, 0, demonstrated[i]),
                          VERVE_OK);
                a = demonstrated[i];
            }
            EXPECT_EQ(actions_[i], a) << "step " << step << " agent " << i;
        }
    }
    for (int i = 0; i < 3; ++i) EXPECT_EQ(saved(agents_[i]), saved(twins[i])) << "agent " << i;
    for (auto* t : twins) verve_agent_destroy(t);
}

TEST_F(BatchRefusal, OneBadObservationRefusesTheWholeCall) {
    continuous_[1] = std::numeric_limits<float>::quiet_NaN();
    discrete_[2] = 4;  // out of range: 4 values
    EXPECT_EQ(update(), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(verve_last_error()).find("agents[1]"), std::string::npos) << verve_last_error();
    EXPECT_EQ(results_[0], VERVE_OK);
    EXPECT_EQ(results_[1], VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(results_[2], VERVE_ERROR_INVALID_ARGUMENT);
    expectUnchanged();
}

TEST_F(BatchRefusal, BadRewardDtNullAgentAndOffsetsChangeNothing) {
    rewards_[2] = std::numeric_limits<float>::infinity();
    EXPECT_EQ(update(), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(results_[2], VERVE_ERROR_INVALID_ARGUMENT);
    rewards_[2] = 0.0f;
    EXPECT_EQ(update(0.0f), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(update(std::numeric_limits<float>::quiet_NaN()), VERVE_ERROR_INVALID_ARGUMENT);
    const uint32_t outside[3] = {0, 1, 3};
    EXPECT_EQ(update(0.1f, outside), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(results_[2], VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(verve_last_error()).find("outside the continuous array"), std::string::npos) << verve_last_error();
    verve_agent* keep = agents_[1];
    agents_[1] = nullptr;
    EXPECT_EQ(update(), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(results_[1], VERVE_ERROR_INVALID_ARGUMENT);
    agents_[1] = keep;
    EXPECT_EQ(verve_batch_update(batch_, agents_, 3, rewards_, discrete_, nullptr, 2, continuous_, nullptr, 3, 0.1f,
                                 actions_, nullptr),
              VERVE_ERROR_INVALID_ARGUMENT) << "discrete array too short";
    EXPECT_EQ(verve_batch_update(nullptr, agents_, 3, rewards_, discrete_, nullptr, 3, continuous_, nullptr, 3, 0.1f, actions_, nullptr),
              VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_batch_update(batch_, agents_, 3, nullptr, discrete_, nullptr, 3, continuous_, nullptr, 3, 0.1f, actions_, nullptr),
              VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_batch_update(batch_, agents_, 3, rewards_, discrete_, nullptr, 3, continuous_, nullptr, 3, 0.1f, nullptr, nullptr),
              VERVE_ERROR_INVALID_ARGUMENT);
    expectUnchanged();
    EXPECT_EQ(update(), VERVE_OK) << verve_last_error();
    for (auto r : results_) EXPECT_EQ(r, VERVE_OK);
    EXPECT_EQ(verve_batch_update(batch_, nullptr, 0, nullptr, nullptr, nullptr, 0, nullptr, nullptr, 0, 0.1f, nullptr, nullptr),
              VERVE_OK) << "an empty batch is fine";
}

TEST_F(BatchRefusal, ABatchUpdateDropsTheSaveASizeQueryKept) {
    size_t size = 0;
    ASSERT_EQ(verve_agent_save_memory(agents_[1], nullptr, &size), VERVE_OK);  // keeps the bytes
    ASSERT_EQ(update(), VERVE_OK) << verve_last_error();
    std::string bytes(size + 4096, '\0');
    size_t capacity = bytes.size();
    ASSERT_EQ(verve_agent_save_memory(agents_[1], &bytes[0], &capacity), VERVE_OK);
    bytes.resize(capacity);
    EXPECT_NE(bytes, before_[1]) << "the save of before the batch update was delivered";
    EXPECT_EQ(bytes, saved(agents_[1]));
}

// Issue 32: a call refused as a whole leaves no verdict saying VERVE_OK, nor a stale one.
TEST_F(BatchRefusal, ARefusedCallGivesEveryAgentItsVerdict) {
    const auto expectAll = [&](verve_result code, const char* what) {
        for (int i = 0; i < 3; ++i) EXPECT_EQ(results_[i], code) << what << ": agent " << i;
    };
    EXPECT_EQ(update(0.0f), VERVE_ERROR_INVALID_ARGUMENT);
    expectAll(VERVE_ERROR_INVALID_ARGUMENT, "dt 0");
    EXPECT_EQ(update(std::numeric_limits<float>::quiet_NaN()), VERVE_ERROR_INVALID_ARGUMENT);
    expectAll(VERVE_ERROR_INVALID_ARGUMENT, "dt NaN");
    for (auto& r : results_) r = VERVE_OK;  // stale verdicts of an earlier call
    EXPECT_EQ(verve_batch_update(batch_, agents_, 3, nullptr, discrete_, nullptr, 3, continuous_, nullptr, 3, 0.1f,
                                 actions_, results_),
              VERVE_ERROR_INVALID_ARGUMENT);
    expectAll(VERVE_ERROR_INVALID_ARGUMENT, "rewards NULL");
    for (auto& r : results_) r = VERVE_OK;
    EXPECT_EQ(verve_batch_update(batch_, agents_, 3, rewards_, discrete_, nullptr, 3, continuous_, nullptr, 3, 0.1f,
                                 nullptr, results_),
              VERVE_ERROR_INVALID_ARGUMENT);
    expectAll(VERVE_ERROR_INVALID_ARGUMENT, "out_actions NULL");
    for (auto& r : results_) r = VERVE_OK;
    EXPECT_EQ(verve_batch_update(nullptr, agents_, 3, rewards_, discrete_, nullptr, 3, continuous_, nullptr, 3, 0.1f,
                                 actions_, results_),
              VERVE_ERROR_INVALID_ARGUMENT);
    expectAll(VERVE_ERROR_INVALID_ARGUMENT, "batch NULL");
    expectUnchanged();
}

// A host job system that, while the batch call holds its flags, tries what another thread of
// the game might: a second batch call over the same agents, destroying the batch, an agent, the brain.
struct Meddler {
    verve_batch* other = nullptr;
    verve_batch* self = nullptr;
    verve_agent* const* agents = nullptr;
    verve_brain* brain = nullptr;
    verve_result otherResult = VERVE_OK;
    verve_result otherResults[3] = {VERVE_OK, VERVE_OK, VERVE_OK};
    bool batchSurvived = false, agentSurvived = false;
};

void* VERVE_CALL enqueueMeddling(verve_task_fn task, uint32_t count, uint32_t, void* taskContext, void* user) {
    auto* m = static_cast<Meddler*>(user);
    const float rewards[3] = {0, 0, 0};
    const float continuous[3] = {0.1f, 0.2f, 0.3f};
    uint32_t actions[3];
    m->otherResult = verve_batch_update(m->other, m->agents, 3, rewards, nullptr, nullptr, 0, continuous, nullptr, 3,
                                        0.1f, actions, m->otherResults);
    verve_batch_destroy(m->self);  // refused: this call is inside it
    m->batchSurvived = std::string(verve_last_error()).find("not destroyed") != std::string::npos;
    verve_agent_destroy(m->agents[0]);
    m->agentSurvived = std::string(verve_last_error()).find("not destroyed") != std::string::npos;
    verve_brain_destroy(m->brain);  // allowed: the bodies' calls do not use the brain's handle
    m->brain = nullptr;
    task(0, count, 0, taskContext);
    return nullptr;
}

TEST(BatchInUse, OverlappingCallsAndDestroysAreRefusedWithVerdicts) {
    const verve_agent_desc d = shape(0, 1, 10, 2, 3);
    Meddler m;
    ASSERT_EQ(verve_brain_create(&d, &m.brain), VERVE_OK);
    verve_agent* agents[3] = {};
    for (auto*& a : agents) ASSERT_EQ(verve_brain_create_body(m.brain, &a), VERVE_OK);
    m.agents = agents;
    verve_batch_desc bd;
    verve_batch_desc_default(&bd);
    bd.worker_count = 1;
    ASSERT_EQ(verve_batch_create(&bd, &m.other), VERVE_OK);
    bd.enqueue_task = enqueueMeddling;
    bd.finish_task = finishNever;
    bd.user_context = &m;
    ASSERT_EQ(verve_batch_create(&bd, &m.self), VERVE_OK);
    const float rewards[3] = {0, 0, 0};
    const float continuous[3] = {0.1f, 0.2f, 0.3f};
    uint32_t actions[3];
    verve_result results[3];
    ASSERT_EQ(verve_batch_update(m.self, agents, 3, rewards, nullptr, nullptr, 0, continuous, nullptr, 3, 0.1f, actions,
                                 results),
              VERVE_OK) << verve_last_error();
    EXPECT_EQ(m.otherResult, VERVE_ERROR_INVALID_STATE);
    for (auto r : m.otherResults) EXPECT_EQ(r, VERVE_ERROR_INVALID_STATE) << "a verdict of the refused call";
    EXPECT_TRUE(m.batchSurvived) << "verve_batch_destroy freed a batch inside its own call";
    EXPECT_TRUE(m.agentSurvived);
    EXPECT_EQ(m.brain, nullptr);
    // The bodies outlive their brain's handle and still work.
    ASSERT_EQ(verve_batch_update(m.other, agents, 3, rewards, nullptr, nullptr, 0, continuous, nullptr, 3, 0.1f, actions,
                                 results),
              VERVE_OK) << verve_last_error();
    verve_batch_destroy(m.self);
    verve_batch_destroy(m.other);
    for (auto* a : agents) verve_agent_destroy(a);
}

TEST(BatchDesc, BadDescriptorsAreRefused) {
    verve_batch* b = nullptr;
    EXPECT_EQ(verve_batch_desc_default(nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    verve_batch_desc d;
    verve_batch_desc_default(&d);
    EXPECT_EQ(d.worker_count, 0u);
    EXPECT_EQ(verve_batch_create(nullptr, &b), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_batch_create(&d, nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    verve_batch_desc wrong = d;
    wrong.struct_size = 4;
    EXPECT_EQ(verve_batch_create(&wrong, &b), VERVE_ERROR_INVALID_ARGUMENT);
    wrong = d;
    wrong.enqueue_task = enqueueInline;  // without finish_task
    EXPECT_EQ(verve_batch_create(&wrong, &b), VERVE_ERROR_INVALID_ARGUMENT);
    wrong.finish_task = finishNever;  // with callbacks, but no worker count
    EXPECT_EQ(verve_batch_create(&wrong, &b), VERVE_ERROR_INVALID_ARGUMENT);
    wrong = d;
    wrong.worker_count = 100000;
    EXPECT_EQ(verve_batch_create(&wrong, &b), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(b, nullptr);
    ASSERT_EQ(verve_batch_create(&d, &b), VERVE_OK);
    uint32_t n = 0;
    EXPECT_EQ(verve_batch_get_worker_count(b, &n), VERVE_OK);
    EXPECT_GE(n, 1u) << "0 means the machine's thread count";
    EXPECT_EQ(verve_batch_get_worker_count(b, nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_batch_get_worker_count(nullptr, &n), VERVE_ERROR_INVALID_ARGUMENT);
    verve_batch_destroy(b);
    verve_batch_destroy(nullptr);
}

// ---- one brain, many bodies -------------------------------------------------------------

TEST(Brain, BodiesShareWhatTheyLearn) {
    const verve_agent_desc d = shape(0, 1, 10, 2, 3);
    verve_brain* brain = nullptr;
    ASSERT_EQ(verve_brain_create(&d, &brain), VERVE_OK);
    verve_agent *teacher = nullptr, *pupil = nullptr;
    ASSERT_EQ(verve_brain_create_body(brain, &teacher), VERVE_OK);
    ASSERT_EQ(verve_brain_create_body(brain, &pupil), VERVE_OK);
    // The teacher alone lives at 0.5 and is rewarded there; the pupil never learns anything itself.
    const float here = 0.5f;
    uint32_t action = 0;
    for (int t = 0; t < 300; ++t) {
        ASSERT_EQ(verve_agent_update(teacher, 1.0f, nullptr, 0, &here, 1, 0.1f, &action), VERVE_OK);
    }
    ASSERT_EQ(verve_agent_set_learning(pupil, 0), VERVE_OK);
    ASSERT_EQ(verve_agent_update(pupil, 0.0f, nullptr, 0, &here, 1, 0.1f, &action), VERVE_OK);
    float value = 0.0f;
    ASSERT_EQ(verve_agent_get_value(pupil, &value), VERVE_OK);
    EXPECT_GT(value, 1.0f) << "the pupil's brain knows what the teacher learned";
    uint32_t rbfs = 0, pupilRbfs = 0;
    EXPECT_EQ(verve_brain_get_rbf_count(brain, &rbfs), VERVE_OK);
    EXPECT_EQ(verve_agent_get_rbf_count(pupil, &pupilRbfs), VERVE_OK);
    EXPECT_EQ(rbfs, pupilRbfs);
    // A separate agent with the same seed and experience knows nothing of it.
    verve_agent* stranger = nullptr;
    ASSERT_EQ(verve_agent_create(&d, &stranger), VERVE_OK);
    ASSERT_EQ(verve_agent_update(stranger, 0.0f, nullptr, 0, &here, 1, 0.1f, &action), VERVE_OK);
    ASSERT_EQ(verve_agent_get_value(stranger, &value), VERVE_OK);
    EXPECT_EQ(value, 0.0f);
    verve_agent_destroy(stranger);
    // Destroying the brain first is fine: the bodies keep it.
    verve_brain_destroy(brain);
    ASSERT_EQ(verve_agent_update(teacher, 1.0f, nullptr, 0, &here, 1, 0.1f, &action), VERVE_OK);
    verve_agent_destroy(teacher);
    verve_agent_destroy(pupil);
}

// A batch's bodies of one brain act against the brain as the call found it (docs/crowds.md): here
// the odd bodies learn nothing in the last call, so each chooses what a copy of it, made just
// before the call and learning nothing, chooses for the same input, and values its state alike,
// though the even bodies before them in the array have learned in the same call by then.
TEST(Brain, BodiesInABatchActOnTheBrainAsTheCallFoundIt) {
    const verve_agent_desc d = shape(0, 2, 6, 3, 9);
    verve_brain* brain = nullptr;
    ASSERT_EQ(verve_brain_create(&d, &brain), VERVE_OK);
    constexpr uint32_t kBodies = 12;
    std::vector<verve_agent*> bodies(kBodies);
    for (auto*& b : bodies) ASSERT_EQ(verve_brain_create_body(brain, &b), VERVE_OK);
    std::vector<float> sensors(2 * kBodies), rewards(kBodies);
    std::vector<uint32_t> actions(kBodies, 0);
    for (uint32_t i = 0; i < kBodies; ++i) {
        sensors[2 * i] = std::sin(1.7f * static_cast<float>(i));
        sensors[2 * i + 1] = std::cos(0.7f * static_cast<float>(i));
    }
    verve_batch* batch = makeBatch(2);
    auto step = [&] {
        for (uint32_t i = 0; i < kBodies; ++i) rewards[i] = actions[i] == i % 3 ? 0.5f : -0.1f;
        ASSERT_EQ(verve_batch_update(batch, bodies.data(), kBodies, rewards.data(), nullptr, nullptr, 0, sensors.data(),
                                     nullptr, 2 * kBodies, 0.1f, actions.data(), nullptr),
                  VERVE_OK)
            << verve_last_error();
    };
    for (int t = 0; t < 30; ++t) step();  // every body's state now has its RBF: no step grows the brain
    const std::string start = saved(bodies[0]);
    std::vector<verve_agent*> copies(kBodies);
    for (uint32_t i = 1; i < kBodies; i += 2) {
        ASSERT_EQ(verve_agent_set_learning(bodies[i], 0), VERVE_OK);
        const std::string xml = saved(bodies[i]);
        ASSERT_EQ(verve_agent_load_memory(xml.data(), xml.size(), &copies[i]), VERVE_OK);
    }
    uint32_t before = 0, after = 0;
    ASSERT_EQ(verve_brain_get_rbf_count(brain, &before), VERVE_OK);
    step();
    ASSERT_EQ(verve_brain_get_rbf_count(brain, &after), VERVE_OK);
    ASSERT_EQ(before, after);
    EXPECT_NE(saved(bodies[0]), start) << "the even bodies' changes reached the brain";
    for (uint32_t i = 1; i < kBodies; i += 2) {
        uint32_t action = 0;
        ASSERT_EQ(verve_agent_update(copies[i], rewards[i], nullptr, 0, &sensors[2 * i], 2, 0.1f, &action), VERVE_OK);
        EXPECT_EQ(actions[i], action) << "body " << i;
        float bodyValue = 0.0f, copyValue = 0.0f;
        ASSERT_EQ(verve_agent_get_value(bodies[i], &bodyValue), VERVE_OK);
        ASSERT_EQ(verve_agent_get_value(copies[i], &copyValue), VERVE_OK);
        EXPECT_EQ(bodyValue, copyValue) << "body " << i;
        verve_agent_destroy(copies[i]);
    }
    verve_batch_destroy(batch);
    for (auto* a : bodies) verve_agent_destroy(a);
    verve_brain_destroy(brain);
}

TEST(Brain, BodiesHaveTheirOwnRandomStreamsAndTheSameSeedRepeats) {
    const verve_agent_desc d = shape(0, 1, 10, 4, 3);
    auto actionsOf = [&](int bodies) {
        verve_brain* brain = nullptr;
        EXPECT_EQ(verve_brain_create(&d, &brain), VERVE_OK);
        std::vector<verve_agent*> b(static_cast<std::size_t>(bodies));
        for (auto*& x : b) EXPECT_EQ(verve_brain_create_body(brain, &x), VERVE_OK);
        std::vector<std::vector<uint32_t>> out(b.size());
        const float here = 0.0f;
        for (int t = 0; t < 40; ++t) {
            for (std::size_t i = 0; i < b.size(); ++i) {
                uint32_t a = 0;
                EXPECT_EQ(verve_agent_update(b[i], 0.0f, nullptr, 0, &here, 1, 0.1f, &a), VERVE_OK);
                out[i].push_back(a);
            }
        }
        for (auto* x : b) verve_agent_destroy(x);
        verve_brain_destroy(brain);
        return out;
    };
    const auto first = actionsOf(2), again = actionsOf(2);
    EXPECT_EQ(first, again);
    EXPECT_NE(first[0], first[1]) << "two bodies drew the same random actions";
}

TEST(Brain, SavesLoadAsBrainsAndAsAgents) {
    const verve_agent_desc d = shape(3, 1, 10, 2, 8);
    verve_brain* brain = nullptr;
    ASSERT_EQ(verve_brain_create(&d, &brain), VERVE_OK);
    verve_agent* body = nullptr;
    ASSERT_EQ(verve_brain_create_body(brain, &body), VERVE_OK);
    uint32_t action = 0;
    for (int t = 0; t < 100; ++t) {
        const int32_t k = t % 3;
        const float x = std::sin(0.3f * static_cast<float>(t));
        ASSERT_EQ(verve_agent_update(body, action == 1 ? 1.0f : 0.0f, &k, 1, &x, 1, 0.1f, &action), VERVE_OK);
    }
    size_t size = 0;
    EXPECT_EQ(verve_brain_save_memory(brain, nullptr, &size), VERVE_OK);
    std::string xml(size, '\0');
    size_t small = size - 1;
    EXPECT_EQ(verve_brain_save_memory(brain, &xml[0], &small), VERVE_ERROR_BUFFER_TOO_SMALL);
    EXPECT_EQ(small, size);
    ASSERT_EQ(verve_brain_save_memory(brain, &xml[0], &size), VERVE_OK);

    // As a brain: same RBFs, and a body of it values states as the original's bodies do.
    verve_brain* copy = nullptr;
    ASSERT_EQ(verve_brain_load_memory(xml.data(), xml.size(), &copy), VERVE_OK) << verve_last_error();
    uint32_t a = 0, b = 0;
    verve_brain_get_rbf_count(brain, &a);
    verve_brain_get_rbf_count(copy, &b);
    EXPECT_EQ(a, b);
    size_t size2 = 0;
    verve_brain_save_memory(copy, nullptr, &size2);
    std::string xml2(size2, '\0');
    verve_brain_save_memory(copy, &xml2[0], &size2);
    EXPECT_EQ(xml2, xml) << "save, load, save again gives the same bytes";
    // As an agent, and an agent's (a body's) save as a brain.
    verve_agent* asAgent = nullptr;
    EXPECT_EQ(verve_agent_load_memory(xml.data(), xml.size(), &asAgent), VERVE_OK) << verve_last_error();
    const std::string bodySave = saved(body);
    verve_brain* fromBody = nullptr;
    EXPECT_EQ(verve_brain_load_memory(bodySave.data(), bodySave.size(), &fromBody), VERVE_OK) << verve_last_error();
    // Files, atomically as agents are saved.
    const std::string path = ::testing::TempDir() + "crowd_brain.xml";
    EXPECT_EQ(verve_brain_save(brain, path.c_str()), VERVE_OK) << verve_last_error();
    verve_brain* fromFile = nullptr;
    EXPECT_EQ(verve_brain_load(path.c_str(), &fromFile), VERVE_OK) << verve_last_error();
    // Corrupt data is refused and hands out nothing.
    verve_brain* none = nullptr;
    std::string bad = xml;
    bad.replace(bad.find("<weights"), 8, "<weighXs");
    EXPECT_NE(verve_brain_load_memory(bad.data(), bad.size(), &none), VERVE_OK);
    EXPECT_EQ(verve_brain_load_memory(xml.data(), xml.size() / 2, &none), VERVE_ERROR_FORMAT);
    EXPECT_EQ(verve_brain_load("/nonexistent/dir/brain.xml", &none), VERVE_ERROR_IO);
    EXPECT_EQ(none, nullptr);
    EXPECT_EQ(verve_brain_save(nullptr, path.c_str()), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_brain_save(brain, nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    for (auto* x : {copy, fromBody, fromFile, brain}) verve_brain_destroy(x);
    verve_agent_destroy(asAgent);
    verve_agent_destroy(body);
}

TEST(Brain, BadArgumentsAreRefused) {
    verve_brain* brain = nullptr;
    verve_agent* body = nullptr;
    verve_agent_desc d = shape(0, 1, 10, 2, 1);
    EXPECT_EQ(verve_brain_create(nullptr, &brain), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_brain_create(&d, nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    d.num_actions = 0;
    EXPECT_EQ(verve_brain_create(&d, &brain), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(brain, nullptr);
    EXPECT_EQ(verve_brain_create_body(nullptr, &body), VERVE_ERROR_INVALID_ARGUMENT);
    uint32_t n = 0;
    EXPECT_EQ(verve_brain_get_rbf_count(nullptr, &n), VERVE_ERROR_INVALID_ARGUMENT);
    size_t size = 0;
    EXPECT_EQ(verve_brain_save_memory(nullptr, nullptr, &size), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_brain_load_memory(nullptr, 10, &brain), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_brain_load(nullptr, &brain), VERVE_ERROR_INVALID_ARGUMENT);
    d.num_actions = 2;
    ASSERT_EQ(verve_brain_create(&d, &brain), VERVE_OK);
    EXPECT_EQ(verve_brain_create_body(brain, nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_brain_get_rbf_count(brain, nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(verve_brain_save_memory(brain, nullptr, nullptr), VERVE_ERROR_INVALID_ARGUMENT);
    verve_brain_destroy(brain);
    verve_brain_destroy(nullptr);
}

}  // namespace
