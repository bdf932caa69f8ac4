// Which continuous sensors share an RBF lattice (AgentDescriptor::grouping). One lattice over n
// sensors needs resolution^n RBFs to cover them: fine for the thesis's 2-4 sensors, hopeless for
// an NPC's dozen raycasts. Tile coding's answer is several codings over subsets of the inputs,
// summed: memory and work then grow with the number of subsets, and each generalises across the
// sensors it leaves out (docs/algorithm.md, "Many sensors").
#pragma once
#include <cstdint>
#include <vector>

#include "verve/agent_descriptor.hpp"

namespace verve::core {

// Up to this many continuous sensors, Auto keeps the thesis's single lattice: it measured best
// there (docs/algorithm.md), and every existing task and save has at most 4.
constexpr std::size_t kJointLatticeSensors = 4;

// The groups of an agent's representation, each a bitmask of continuous sensors, in lattice
// order: one group of every sensor (Joint, or Auto up to kJointLatticeSensors); beyond that, Auto
// gives each sensor a lattice of its own and each neighbouring pair (i, i + 1) one together, so
// sensors listed next to each other (adjacent rays, bearing and distance) are learned jointly;
// Custom is the descriptor's own list. With no continuous sensors: one group, 0.
std::vector<std::uint64_t> sensorGroups(const AgentDescriptor& d);

// The sensors of a group, lowest first.
std::vector<std::uint32_t> groupSensors(std::uint64_t group);

}  // namespace verve::core
