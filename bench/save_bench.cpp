// Saving and loading through the C ABI (docs/performance.md, "Saving"): an agent of 10,000 RBFs
// (the 2-D lattice at resolution 100, 3 actions) after some learning.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "verve_c.h"

namespace {

verve_agent* tenThousandRbfs() {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_continuous_sensors = 2;
    d.resolution = 100;
    d.num_actions = 3;
    d.rbf_allocation = VERVE_RBF_FULL;
    verve_agent* agent = nullptr;
    if (verve_agent_create(&d, &agent) != VERVE_OK) return nullptr;
    for (int i = 0; i < 5000; ++i) {
        const float t = 0.013f * static_cast<float>(i);
        const float sensors[2] = {0.9f * std::sin(1.3f * t), 0.9f * std::sin(0.7f * t + 1.0f)};
        std::uint32_t action = 0;
        verve_agent_update(agent, std::sin(0.065f * static_cast<float>(i)), nullptr, 0, sensors, 2, 0.1f, &action);
    }
    return agent;
}

using MemorySave = verve_result (*)(const verve_agent*, void*, size_t*);

std::vector<char> savedBy(MemorySave save, verve_agent* agent) {
    size_t size = 0;
    save(agent, nullptr, &size);
    std::vector<char> buffer(size);
    save(agent, buffer.data(), &size);
    return buffer;
}

// The documented two calls: how big, then into the buffer.
void BM_SaveMemoryTwoCalls(benchmark::State& state, MemorySave save) {
    verve_agent* agent = tenThousandRbfs();
    std::vector<char> buffer;
    for (auto _ : state) {
        size_t size = 0;
        save(agent, nullptr, &size);
        buffer.resize(size);
        save(agent, buffer.data(), &size);
        benchmark::DoNotOptimize(buffer.data());
    }
    state.counters["bytes"] = static_cast<double>(buffer.size());
    verve_agent_destroy(agent);
}
BENCHMARK_CAPTURE(BM_SaveMemoryTwoCalls, xml, verve_agent_save_memory)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SaveMemoryTwoCalls, binary, verve_agent_save_memory_binary)->Unit(benchmark::kMillisecond);

void BM_LoadMemory(benchmark::State& state, MemorySave save) {
    verve_agent* agent = tenThousandRbfs();
    const std::vector<char> buffer = savedBy(save, agent);
    for (auto _ : state) {
        verve_agent* loaded = nullptr;
        verve_agent_load_memory(buffer.data(), buffer.size(), &loaded);
        verve_agent_destroy(loaded);
    }
    verve_agent_destroy(agent);
}
BENCHMARK_CAPTURE(BM_LoadMemory, xml, verve_agent_save_memory)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadMemory, binary, verve_agent_save_memory_binary)->Unit(benchmark::kMillisecond);

}  // namespace
