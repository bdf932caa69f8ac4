// Saving and loading through the C ABI (docs/performance.md, "Saving"): an agent of 10,000 RBFs
// (the 2-D lattice at resolution 100, 3 actions) after some learning, and a brain of the same shape
// trained by one body.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "verve_c.h"

namespace {

verve_agent_desc tenThousandRbfs() {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_continuous_sensors = 2;
    d.resolution = 100;
    d.num_actions = 3;
    d.rbf_allocation = VERVE_RBF_FULL;
    return d;
}

void train(verve_agent* agent) {
    for (int i = 0; i < 5000; ++i) {
        const float t = 0.013f * static_cast<float>(i);
        const float sensors[2] = {0.9f * std::sin(1.3f * t), 0.9f * std::sin(0.7f * t + 1.0f)};
        std::uint32_t action = 0;
        verve_agent_update(agent, std::sin(0.065f * static_cast<float>(i)), nullptr, 0, sensors, 2, 0.1f, &action);
    }
}

// What the benchmarks save and load: an agent, or a brain (its body trained it, then went).
struct AgentKind {
    using Handle = verve_agent;
    using Save = verve_result (*)(const Handle*, void*, size_t*);
    static Handle* make() {
        const verve_agent_desc d = tenThousandRbfs();
        verve_agent* agent = nullptr;
        if (verve_agent_create(&d, &agent) != VERVE_OK) return nullptr;
        train(agent);
        return agent;
    }
    static verve_result load(const void* data, size_t size, Handle** out) { return verve_agent_load_memory(data, size, out); }
    static void destroy(Handle* agent) { verve_agent_destroy(agent); }
};

struct BrainKind {
    using Handle = verve_brain;
    using Save = verve_result (*)(const Handle*, void*, size_t*);
    static Handle* make() {
        const verve_agent_desc d = tenThousandRbfs();
        verve_brain* brain = nullptr;
        verve_agent* body = nullptr;
        if (verve_brain_create(&d, &brain) != VERVE_OK) return nullptr;
        if (verve_brain_create_body(brain, &body) == VERVE_OK) train(body);
        verve_agent_destroy(body);
        return brain;
    }
    static verve_result load(const void* data, size_t size, Handle** out) { return verve_brain_load_memory(data, size, out); }
    static void destroy(Handle* brain) { verve_brain_destroy(brain); }
};

template <typename Kind>
std::vector<char> savedBy(typename Kind::Save save, typename Kind::Handle* handle) {
    size_t size = 0;
    save(handle, nullptr, &size);
    std::vector<char> buffer(size);
    save(handle, buffer.data(), &size);
    return buffer;
}

// The documented two calls: how big, then into the buffer.
template <typename Kind>
void BM_SaveMemoryTwoCalls(benchmark::State& state, Kind, typename Kind::Save save) {
    typename Kind::Handle* handle = Kind::make();
    std::vector<char> buffer;
    for (auto _ : state) {
        size_t size = 0;
        save(handle, nullptr, &size);
        buffer.resize(size);
        save(handle, buffer.data(), &size);
        benchmark::DoNotOptimize(buffer.data());
    }
    state.counters["bytes"] = static_cast<double>(buffer.size());
    Kind::destroy(handle);
}
BENCHMARK_CAPTURE(BM_SaveMemoryTwoCalls, xml, AgentKind{}, verve_agent_save_memory)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SaveMemoryTwoCalls, binary, AgentKind{}, verve_agent_save_memory_binary)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SaveMemoryTwoCalls, brain_xml, BrainKind{}, verve_brain_save_memory)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SaveMemoryTwoCalls, brain_binary, BrainKind{}, verve_brain_save_memory_binary)->Unit(benchmark::kMillisecond);

template <typename Kind>
void BM_LoadMemory(benchmark::State& state, Kind, typename Kind::Save save) {
    typename Kind::Handle* handle = Kind::make();
    const std::vector<char> buffer = savedBy<Kind>(save, handle);
    for (auto _ : state) {
        typename Kind::Handle* loaded = nullptr;
        Kind::load(buffer.data(), buffer.size(), &loaded);
        Kind::destroy(loaded);
    }
    state.counters["bytes"] = static_cast<double>(buffer.size());
    Kind::destroy(handle);
}
BENCHMARK_CAPTURE(BM_LoadMemory, xml, AgentKind{}, verve_agent_save_memory)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadMemory, binary, AgentKind{}, verve_agent_save_memory_binary)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadMemory, brain_xml, BrainKind{}, verve_brain_save_memory)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadMemory, brain_binary, BrainKind{}, verve_brain_save_memory_binary)->Unit(benchmark::kMillisecond);

}  // namespace
