// The RBF lattices of an agent's representation: its sensor groups (core/sensor_groups.hpp), and
// beside them the lattices its adaptations add (core/fine_lattice.hpp, core/pairs_beside.hpp).
#pragma once
#include <cstdint>
#include <vector>

#include "verve/agent_descriptor.hpp"

namespace verve::core {

// One lattice of a representation: which continuous sensors (a bitmask) at what resolution.
struct LatticeSpec {
    std::uint64_t sensors = 0;
    std::uint32_t resolution = 0;
    // The share of its expected activation sum in the sum the learning rates are divided by
    // (core/state_representation.hpp): 1 for the agent's own groups, less for a lattice added
    // beside them.
    float share = 1.0f;
};

// Every lattice of an agent's representation, in feature-key order: its sensor groups at the
// descriptor's resolution, then the fine twin of a lattice of 1-2 sensors (Adaptation::FineLattice)
// or the neighbouring pairs beside a lattice of 3-4 (Adaptation::PairsBeside). Saves keep the lattices they
// were made with: the bits are saved with the descriptor.
std::vector<LatticeSpec> lattices(const AgentDescriptor& d);

}  // namespace verve::core
