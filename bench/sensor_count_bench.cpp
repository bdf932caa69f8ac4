// Many continuous sensors (docs/performance.md, "Many sensors"): RBFs, heap and the cost of one
// update for 4, 8, 16 and 32 sensors, at defaults (Auto: a lattice per sensor and per neighbouring
// pair beyond 4, each learning at its own rate), with one rate for all those lattices, and with one
// joint lattice over all (the thesis) up to 16: one lattice spans at most
// DescriptorLimits::kMaxLatticeSensors, so Joint over 32 is refused. Each sensor follows a smooth
// path of its own frequency, as an NPC's rays and speeds do; 20,000 updates (33 simulated minutes at
// 0.1 s) come before the timing.
#include "smooth_paths.hpp"

namespace {

using namespace verve;

void run(benchmark::State& state, SensorGrouping grouping, std::uint32_t adaptation = Adaptation::All) {
    AgentDescriptor d;
    for (std::int64_t i = 0; i < state.range(0); ++i) d.addContinuousSensor();
    d.numActions = 5;
    d.grouping = grouping;
    d.adaptation = adaptation;
    bench::timeOnSmoothPaths(state, d);
}

void BM_SensorsAuto(benchmark::State& state) { run(state, SensorGrouping::Auto); }
BENCHMARK(BM_SensorsAuto)->Arg(4)->Arg(8)->Arg(16)->Arg(32)->ArgName("sensors");

// The same groups with one rate for all (Adaptation::GroupRates cleared): what the rates cost.
void BM_SensorsAutoOneRate(benchmark::State& state) {
    run(state, SensorGrouping::Auto, Adaptation::All & ~Adaptation::GroupRates);
}
BENCHMARK(BM_SensorsAutoOneRate)->Arg(8)->Arg(16)->Arg(32)->ArgName("sensors");

void BM_SensorsJoint(benchmark::State& state) { run(state, SensorGrouping::Joint); }
BENCHMARK(BM_SensorsJoint)->Arg(4)->Arg(8)->Arg(16)->ArgName("sensors");

}  // namespace
