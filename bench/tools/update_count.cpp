// Runs a fixed number of updates after a warm-up, for instruction counts that a loaded machine
// cannot blur (docs/performance.md):
//   valgrind --tool=callgrind --toggle-collect='*measuredUpdates*' build/bench/verve_update_count cart-pole
// Shapes: cart-pole (20,000 warm-up steps, 3,000 counted), dense-4d-R and dense-2d-R (the full
// lattice at resolution R; 500 warm-up, 300 counted).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "bench_shapes.hpp"

namespace {

// Not inlined, so that callgrind can count exactly its calls.
template <typename Run>
__attribute__((noinline)) void measuredUpdates(Run& run, int count) {
    for (int i = 0; i < count; ++i) run.step();
}

template <typename Run>
void warmAndMeasure(Run& run, int warm, int count) {
    for (int i = 0; i < warm; ++i) run.step();
    measuredUpdates(run, count);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string shape = argc > 1 ? argv[1] : "";
    if (shape == "cart-pole") {
        verve::Agent agent(verve::bench::cartPoleAgent());
        verve::bench::CartPoleRun run(agent);
        warmAndMeasure(run, 20000, 3000);
        std::printf("cart-pole: 3000 updates counted at %zu RBFs\n", agent.rbfCount());
        return 0;
    }
    int dims = 0;
    unsigned resolution = 0;
    if (std::sscanf(shape.c_str(), "dense-%dd-%u", &dims, &resolution) == 2 && (dims == 2 || dims == 4) &&
        resolution >= 1 && resolution <= (dims == 2 ? 400u : 40u)) {
        const auto d = verve::bench::denseAgent(dims, resolution);
        verve::Agent agent(d);
        verve::bench::PathRun run(agent, d);
        warmAndMeasure(run, 500, 300);
        std::printf("%s: 300 updates counted at %zu RBFs\n", shape.c_str(), agent.rbfCount());
        return 0;
    }
    std::fprintf(stderr, "usage: verve_update_count cart-pole | dense-4d-R | dense-2d-R (R: resolution, at most 40 in 4-D, 400 in 2-D)\n");
    return 2;
}
