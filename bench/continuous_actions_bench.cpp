// Continuous actions (docs/performance.md, "Continuous actions and reward stretches"): the cost of
// one update of an NPC that steers and throttles, as two continuous actions (4 actor columns beside
// one discrete action) and as 3 x 3 action branches (6 neurons), with 4 continuous sensors on smooth
// paths; 20,000 updates come before the timing.
#include "smooth_paths.hpp"

namespace {

using namespace verve;

void run(benchmark::State& state, bool continuous) {
    AgentDescriptor d;
    for (int i = 0; i < 4; ++i) d.addContinuousSensor();
    if (continuous) {
        d.numActions = 1;
        d.continuousActions = 2;
    } else {
        d.setActionBranches({3, 3});
    }
    bench::timeOnSmoothPaths(state, d);
}

void BM_SteerAndThrottleContinuous(benchmark::State& state) { run(state, true); }
BENCHMARK(BM_SteerAndThrottleContinuous);

void BM_SteerAndThrottleBranches(benchmark::State& state) { run(state, false); }
BENCHMARK(BM_SteerAndThrottleBranches);

}  // namespace
