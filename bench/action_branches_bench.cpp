// Action branches (docs/performance.md, "Action branches"): the cost of one update of an NPC that
// moves x turns x uses (3 x 3 x 2) as three branches (8 actor neurons) and as the same 18 combined
// actions in one set (18 neurons), with 4 continuous sensors on smooth paths; 20,000 updates come
// before the timing.
#include "smooth_paths.hpp"

namespace {

using namespace verve;

void run(benchmark::State& state, bool branches) {
    AgentDescriptor d;
    for (int i = 0; i < 4; ++i) d.addContinuousSensor();
    if (branches) d.setActionBranches({3, 3, 2});
    else d.numActions = 18;
    bench::timeOnSmoothPaths(state, d);
}

void BM_ActionBranches(benchmark::State& state) { run(state, true); }
BENCHMARK(BM_ActionBranches);

void BM_ActionsCombinedInOneSet(benchmark::State& state) { run(state, false); }
BENCHMARK(BM_ActionsCombinedInOneSet);

}  // namespace
