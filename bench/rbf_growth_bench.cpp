// Cost of one update as the RBF count grows (docs/performance.md, "Cost does not follow the RBF
// count"). Work should follow the RBFs near the input, never the total; in 4-D a cutoff ball of
// radius 4 sigma holds ~1,260 lattice RBFs, so a dense 4-D update is ~1k active features however
// many RBFs exist.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>

#include "heap_bytes.hpp"

#include "verve/agent.hpp"

namespace {

using verve::Agent;
using verve::AgentDescriptor;
using verve::Observation;

// A smooth path through the interior of [-1, 1]^n with incommensurate frequencies per sensor, so
// that over a benchmark run it visits the whole space rather than one corner.
void pathPoint(std::uint64_t step, Observation& o) {
    static constexpr float kFrequency[4] = {1.3f, 0.7f, 1.1f, 0.9f};
    const float t = 0.013f * static_cast<float>(step);
    for (std::size_t d = 0; d < o.continuous.size(); ++d) o.continuous[d] = 0.9f * std::sin(t * kFrequency[d] + float(d));
}

void run(benchmark::State& state, const AgentDescriptor& d) {
    const std::size_t heapBefore = heapBytesInUse();
    Agent agent(d);
    Observation o(d);
    std::uint64_t step = 0;
    auto next = [&] {
        ++step;
        pathPoint(step, o);
        agent.update(std::sin(0.065f * static_cast<float>(step)), o, 0.1f);
    };
    for (int i = 0; i < 2000; ++i) next();
    const std::size_t heap = heapBytesInUse() - heapBefore;
    for (auto _ : state) next();
    state.counters["rbfs"] = static_cast<double>(agent.rbfCount());
    // Heap per RBF, allocator overhead and spare capacity included (0 where it cannot be read).
    state.counters["bytes_per_rbf"] = static_cast<double>(heap) / static_cast<double>(agent.rbfCount());
}

// A dense 4-D space: the full lattice at resolution 6, 10 or 18 (1,296, 10,000 or 104,976 RBFs).
void BM_UpdateDense4D(benchmark::State& state) {
    AgentDescriptor d;
    for (int i = 0; i < 4; ++i) d.addContinuousSensor();
    d.resolution = static_cast<std::uint32_t>(state.range(0));
    d.numActions = 3;
    d.allocation = verve::RbfAllocation::Full;
    run(state, d);
}
BENCHMARK(BM_UpdateDense4D)->Arg(6)->Arg(10)->Arg(18);

// A dense 2-D space: the full lattice at resolution 32, 100 or 320 (1,024, 10,000 or 102,400 RBFs).
void BM_UpdateDense2D(benchmark::State& state) {
    AgentDescriptor d;
    d.addContinuousSensor().addContinuousSensor();
    d.resolution = static_cast<std::uint32_t>(state.range(0));
    d.numActions = 3;
    d.allocation = verve::RbfAllocation::Full;
    run(state, d);
}
BENCHMARK(BM_UpdateDense2D)->Arg(32)->Arg(100)->Arg(320);

}  // namespace
