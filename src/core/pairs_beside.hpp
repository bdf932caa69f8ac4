// Neighbouring pairs beside a lattice of 3-4 sensors (Adaptation::PairsBeside; docs/algorithm.md,
// "Pairs beside a lattice of three or four sensors"). One lattice over 3-4 sensors reads them
// together, as a cart-pole's balance needs, but each RBF then covers a small corner of the space,
// so what two of them decide alone (a car's bearing and distance tell how to steer; a signal and
// a position tell a plate's safe side, whatever two other sensors read) is learned corner by
// corner. Beside that lattice, Auto adds a lattice over each neighbouring pair of sensors (i,
// i + 1), features summed with the joint lattice's (as tile coding sums tilings over subsets of
// the inputs). Measured at defaults (docs/experiments.md has the whole table): a signaled plate
// among 2 distractor sensors 38.4 -> 9.9 steps, the steering car 82.8 -> 69.8 (its scripted
// driver: 73), the Bullet cart-pole 509 -> 448 trials to balance for 1800 s, cart-pole-v1 and
// acrobot-v1 solved in fewer steps (medians 76.7k -> 59.9k and 19.5k -> 11.5k).
#pragma once
#include <vector>

#include "core/lattice_layout.hpp"
#include "verve/agent_descriptor.hpp"

namespace verve::core {

// The fewest sensors that get pairs beside their lattice: a lattice of one or two gets a fine
// twin instead (core/fine_lattice.hpp), and two sensors' one pair is the lattice itself. The most
// is kJointLatticeSensors, past which Auto makes single and pair groups alone.
constexpr std::size_t kPairsBesideMinSensors = 3;
// The share of each pair's expected activation sum in the sum the learning rates are divided by:
// half, as a fine twin counts (core/fine_lattice.hpp). All of it: the Bullet cart-pole 522
// trials, the car 73.1 steps; a third: 420 and 69.0; half: 448 and 69.8. Single-sensor lattices
// beside the pairs as well (Auto's layout beyond 4 sensors) helped the car more (62.7) but slowed
// the cart-pole (527 trials) and left acrobot-v1 stalled for 100k-220k steps on 2 of 100 seeds.
constexpr float kPairsBesideActivationShare = 0.5f;

// Appends the pairs beside out's one lattice when d asks for them (Auto grouping, the bit set)
// and that lattice spans kPairsBesideMinSensors to kJointLatticeSensors sensors. out: the agent's
// sensor groups (core/lattice_layout.hpp).
void addPairsBeside(const AgentDescriptor& d, std::vector<LatticeSpec>& out);

}  // namespace verve::core
