// A finer lattice beside a small one (Adaptation::FineLattice; docs/algorithm.md, "A finer
// lattice beside a small one"). One resolution cannot serve every task: wide RBFs generalise fast
// and let a corridor or a maze be learned in a few trials, but they blur what must be told apart
// within a width (a pendulum balanced near the top, where the right torque flips within 20
// degrees, was learned in 300k steps or never at resolution 10 and in 40k at 14; 14 made a
// 4-sensor task and a steering car slower). A second lattice over the same sensors at twice the
// resolution, its features summed with the coarse ones (as tile coding sums tilings of different
// widths), gives both: the coarse RBFs learn the broad shape at once, the fine ones the detail
// where it matters, and the user need not know which a task wants. Only beside one lattice over up
// to kFineLatticeSensors sensors: over n sensors a fine lattice holds 2^n times the coarse one's
// RBFs and fills in that much more slowly (3 sensors: the steering car 82.8 -> 86.3 steps; 4: a
// signaled plate with distractors 38.4 -> 48.6). Beside the many small lattices of sensor groups
// fine ones also helped (a signaled plate with 6 distractors 18.5 -> 11.2 steps) but doubled the
// features of an update and could hold five times the RBFs: an NPC with a dozen rays pays that on
// every step, so they are not made. A lattice of 3-4 sensors gets its neighbouring pairs beside
// it instead (core/pairs_beside.hpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/lattice_layout.hpp"
#include "verve/agent_descriptor.hpp"

namespace verve::core {

constexpr std::size_t kFineLatticeSensors = 2;
constexpr std::uint32_t kFineLatticeFactor = 2;  // 1.6x put the corridor's RBFs out of step with its cells: 39 -> 196 steps
// The share of a fine lattice's expected activation sum in the sum the learning rates are divided
// by (core/state_representation.hpp). All of it: the coarse RBFs learned half as fast as alone, and
// an NPC's patrol carried over to a new route worse (4.17 -> 2.75 waypoints a minute). None: each
// lattice learned as fast as alone, so a step moved values twice as far, and one brain shared by
// eight NPCs stopped eating more often (the NPC arena, 30 seeds: 3.76 -> 3.01 food per NPC-minute).
// Half: 3.25 waypoints, 3.88 food, and Pendulum-v1 and MountainCar-v0 solved on every seed.
constexpr float kFineActivationShare = 0.5f;

// Appends the fine twin of out's one lattice when d asks for it and that lattice spans 1 to
// kFineLatticeSensors sensors (unless twice the resolution would pass
// DescriptorLimits::kMaxResolution). out: the agent's sensor groups (core/lattice_layout.hpp).
void addFineLattice(const AgentDescriptor& d, std::vector<LatticeSpec>& out);

}  // namespace verve::core
