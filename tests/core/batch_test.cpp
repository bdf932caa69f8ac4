// verve::Batch through the C++ API (issue 32): a call's grouping of agents by brain is its own.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

#include "verve/batch.hpp"
#include "verve/brain.hpp"

namespace verve {
namespace {

AgentDescriptor lattice(std::uint64_t seed) {
    AgentDescriptor d;
    d.discreteSensors = {5};
    d.numActions = 3;
    d.allocation = RbfAllocation::Full;  // nothing grows: with learning off, updates only read the brain
    d.seed = seed;
    return d;
}

// Two crowds, each with its own Batch on its own thread, whose agents include bodies of one
// shared brain (learning off, so the brain is only read). Before issue 32 each call wrote its
// grouping into the shared brain (batchToken / batchGroup), and one call could take the other's
// group number and write past its own table: heap corruption, or agents updated twice or never.
struct Crowd {
    std::vector<Agent> own;    // agents of their own, between the bodies: many groups per call
    std::vector<Agent> bodies;
    std::vector<Agent*> order;
};

// n bodies, each followed by `between` agents of their own.
Crowd makeCrowd(Brain& shared, int n, int between, std::uint64_t seed) {
    Crowd c;
    const auto own = static_cast<std::size_t>(n * between);
    c.own.reserve(own);
    c.bodies.reserve(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < own; ++i) c.own.emplace_back(lattice(seed + i));
    for (int i = 0; i < n; ++i) {
        c.bodies.push_back(shared.makeBody());
        c.bodies.back().setLearning(false);
    }
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
        c.order.push_back(&c.bodies[i]);
        for (int k = 0; k < between; ++k) c.order.push_back(&c.own[i * static_cast<std::size_t>(between) + static_cast<std::size_t>(k)]);
    }
    return c;
}

std::vector<std::uint32_t> step(Batch* batch, Crowd& c, int round) {
    const std::size_t n = c.order.size();
    std::vector<float> rewards(n, 0.1f);
    std::vector<std::int32_t> discrete(n);
    for (std::size_t i = 0; i < n; ++i) discrete[i] = static_cast<std::int32_t>((i + static_cast<std::size_t>(round)) % 5);
    std::vector<std::uint32_t> actions(n, 99);
    if (batch == nullptr) {
        for (std::size_t i = 0; i < n; ++i) {
            const ObservationView v{&discrete[i], 1, nullptr, 0};
            actions[i] = c.order[i]->update(rewards[i], v, 0.1f);
        }
        return actions;
    }
    BatchStep s;
    s.agents = c.order.data();
    s.count = n;
    s.rewards = rewards.data();
    s.discrete = discrete.data();
    s.discreteTotal = n;
    s.dt = 0.1f;
    s.actions = actions.data();
    batch->update(s);
    return actions;
}

TEST(Batch, ConcurrentBatchesMeetingOneBrainKeepTheirGroupingApart) {
    constexpr int kRounds = 1500, kBodies = 16;
    // The reference: the same crowds (same seeds), updated one agent at a time.
    std::vector<std::vector<std::uint32_t>> expected[2];
    {
        Brain shared(lattice(7));
        Crowd crowds[2] = {makeCrowd(shared, kBodies, 1, 100), makeCrowd(shared, kBodies, 4, 200)};
        for (int k = 0; k < 2; ++k) {
            for (int r = 0; r < kRounds; ++r) expected[k].push_back(step(nullptr, crowds[k], r));
        }
    }
    Brain shared(lattice(7));
    Crowd crowds[2] = {makeCrowd(shared, kBodies, 1, 100), makeCrowd(shared, kBodies, 4, 200)};
    std::vector<std::vector<std::uint32_t>> got[2];
    BatchOptions options;
    options.workerCount = 2;
    std::vector<std::thread> threads;
    for (int k = 0; k < 2; ++k) {
        threads.emplace_back([&, k] {
            Batch batch(options);
            for (int r = 0; r < kRounds; ++r) got[k].push_back(step(&batch, crowds[k], r));
        });
    }
    for (auto& t : threads) t.join();
    for (int k = 0; k < 2; ++k) EXPECT_EQ(got[k], expected[k]) << "crowd " << k;
}

}  // namespace
}  // namespace verve
