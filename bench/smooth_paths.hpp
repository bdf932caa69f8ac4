// An agent fed smooth sensor paths, each of its own frequency (as an NPC's rays and speeds move),
// timed per update after 20,000 updates (33 simulated minutes at 0.1 s), with its RBFs and heap.
// Shared by the sensor-count and action-branch benchmarks.
#pragma once
#include <benchmark/benchmark.h>

#include <cmath>

#include "heap_bytes.hpp"
#include "verve/agent.hpp"

namespace verve::bench {

inline void timeOnSmoothPaths(benchmark::State& state, const AgentDescriptor& d) {
    const std::size_t sensors = d.continuousSensors.size();
    const std::size_t heapBefore = heapBytesInUse();
    Agent agent(d);
    Observation obs(d);
    std::uint64_t step = 0;
    auto update = [&] {
        const float t = 0.1f * static_cast<float>(++step);
        for (std::size_t i = 0; i < sensors; ++i) {
            obs.continuous[i] = 0.95f * std::sin(t * (0.31f + 0.173f * static_cast<float>(i)) + static_cast<float>(i));
        }
        benchmark::DoNotOptimize(agent.update(std::sin(0.05f * t), obs, 0.1f));
    };
    for (int i = 0; i < 20000; ++i) update();
    const std::size_t heap = heapBytesInUse() - heapBefore;
    for (auto _ : state) update();
    state.counters["rbfs"] = static_cast<double>(agent.rbfCount());
    state.counters["heap_MB"] = static_cast<double>(heap) / 1e6;  // 0 where the allocator does not say
}

}  // namespace verve::bench
