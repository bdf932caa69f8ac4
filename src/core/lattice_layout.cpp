#include "core/lattice_layout.hpp"

#include "core/fine_lattice.hpp"
#include "core/pairs_beside.hpp"
#include "core/sensor_groups.hpp"

namespace verve::core {

std::vector<LatticeSpec> lattices(const AgentDescriptor& d) {
    std::vector<LatticeSpec> out;
    for (auto group : sensorGroups(d)) out.push_back(LatticeSpec{group, d.resolution});
    addFineLattice(d, out);
    addPairsBeside(d, out);
    return out;
}

}  // namespace verve::core
