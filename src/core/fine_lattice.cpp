#include "core/fine_lattice.hpp"

namespace verve::core {

void addFineLattice(const AgentDescriptor& d, std::vector<LatticeSpec>& out) {
    // Custom grouping with no continuous sensors may list no group at all.
    if (out.size() != 1 || (d.adaptation & Adaptation::FineLattice) == 0) return;
    if (d.resolution > DescriptorLimits::kMaxResolution / kFineLatticeFactor) return;
    const int n = __builtin_popcountll(out[0].sensors);
    if (n >= 1 && static_cast<std::size_t>(n) <= kFineLatticeSensors) {
        out.push_back(LatticeSpec{out[0].sensors, kFineLatticeFactor * d.resolution, kFineActivationShare});
    }
}

}  // namespace verve::core
