#include "core/fine_lattice.hpp"

#include "core/sensor_groups.hpp"

namespace verve::core {

std::vector<LatticeSpec> lattices(const AgentDescriptor& d) {
    std::vector<LatticeSpec> out;
    for (auto group : sensorGroups(d)) out.push_back(LatticeSpec{group, d.resolution, false});
    // Custom grouping with no continuous sensors may list no group at all.
    if (out.size() != 1 || (d.adaptation & Adaptation::FineLattice) == 0) return out;
    if (d.resolution > DescriptorLimits::kMaxResolution / kFineLatticeFactor) return out;
    const int n = __builtin_popcountll(out[0].sensors);
    if (n >= 1 && static_cast<std::size_t>(n) <= kFineLatticeSensors) {
        out.push_back(LatticeSpec{out[0].sensors, kFineLatticeFactor * d.resolution, true});
    }
    return out;
}

}  // namespace verve::core
