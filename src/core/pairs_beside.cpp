#include "core/pairs_beside.hpp"

#include "core/sensor_groups.hpp"

namespace verve::core {

void addPairsBeside(const AgentDescriptor& d, std::vector<LatticeSpec>& out) {
    if (d.grouping != SensorGrouping::Auto || (d.adaptation & Adaptation::PairsBeside) == 0) return;
    if (out.size() != 1) return;
    const std::size_t n = static_cast<std::size_t>(__builtin_popcountll(out[0].sensors));
    if (n < kPairsBesideMinSensors || n > kJointLatticeSensors) return;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        out.push_back(LatticeSpec{std::uint64_t(3) << i, d.resolution, kPairsBesideActivationShare});
    }
}

}  // namespace verve::core
