// Many continuous sensors (docs/performance.md, "Many sensors"): RBFs, heap and the cost of one
// update for 4, 8 and 16 sensors, at defaults (Auto: a lattice per sensor and per neighbouring pair
// beyond 4) and with one joint lattice over all (the thesis). Each sensor follows a smooth path of
// its own frequency, as an NPC's rays and speeds do; 20,000 updates (33 simulated minutes at 0.1 s)
// come before the timing.
#include <benchmark/benchmark.h>

#include <cmath>

#include "heap_bytes.hpp"
#include "verve/agent.hpp"

namespace {

using namespace verve;

void run(benchmark::State& state, SensorGrouping grouping) {
    const auto sensors = static_cast<std::size_t>(state.range(0));
    AgentDescriptor d;
    for (std::size_t i = 0; i < sensors; ++i) d.addContinuousSensor();
    d.numActions = 5;
    d.grouping = grouping;
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

void BM_SensorsAuto(benchmark::State& state) { run(state, SensorGrouping::Auto); }
BENCHMARK(BM_SensorsAuto)->Arg(4)->Arg(8)->Arg(16)->ArgName("sensors");

void BM_SensorsJoint(benchmark::State& state) { run(state, SensorGrouping::Joint); }
BENCHMARK(BM_SensorsJoint)->Arg(4)->Arg(8)->Arg(16)->ArgName("sensors");

}  // namespace
