// Cost of one update as the RBF count grows (docs/performance.md, "Cost does not follow the RBF
// count"), and the heap each RBF takes. Work should follow the RBFs near the input, never the
// total: a cutoff ball of radius 4 sigma holds ~50 lattice RBFs in 2-D and ~1,260 in 4-D (fewer
// near the borders), however many RBFs exist.
#include <benchmark/benchmark.h>

#include "bench_shapes.hpp"
#include "heap_bytes.hpp"

namespace {

using verve::Agent;

void run(benchmark::State& state, int dims) {
    const auto d = verve::bench::denseAgent(dims, static_cast<std::uint32_t>(state.range(0)));
    const std::size_t heapBefore = heapBytesInUse();
    Agent agent(d);
    verve::bench::PathRun path(agent, d);
    for (int i = 0; i < 2000; ++i) path.step();
    const std::size_t heap = heapBytesInUse() - heapBefore;
    for (auto _ : state) path.step();
    state.counters["rbfs"] = static_cast<double>(agent.rbfCount());
    // Heap per RBF, allocator overhead and spare capacity included (0 where it cannot be read).
    state.counters["bytes_per_rbf"] = static_cast<double>(heap) / static_cast<double>(agent.rbfCount());
}

// A dense 4-D space: the full lattice at resolution 6, 10 or 18 (1,296, 10,000 or 104,976 RBFs).
void BM_UpdateDense4D(benchmark::State& state) { run(state, 4); }
BENCHMARK(BM_UpdateDense4D)->Arg(6)->Arg(10)->Arg(18);

// A dense 2-D space: the full lattice at resolution 32, 100 or 320 (1,024, 10,000 or 102,400 RBFs).
void BM_UpdateDense2D(benchmark::State& state) { run(state, 2); }
BENCHMARK(BM_UpdateDense2D)->Arg(32)->Arg(100)->Arg(320);

}  // namespace
