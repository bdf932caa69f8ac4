#include "core/sensor_groups.hpp"

namespace verve::core {

std::vector<std::uint64_t> sensorGroups(const AgentDescriptor& d) {
    const std::size_t n = d.continuousSensors.size();
    const std::uint64_t all = n >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << n) - 1;
    if (d.grouping == SensorGrouping::Custom) return d.sensorGroups;
    if (d.grouping == SensorGrouping::Joint || n <= kJointLatticeSensors) return {all};
    std::vector<std::uint64_t> groups;
    for (std::size_t i = 0; i < n; ++i) groups.push_back(std::uint64_t(1) << i);
    for (std::size_t i = 0; i + 1 < n; ++i) groups.push_back(std::uint64_t(3) << i);
    return groups;
}

std::vector<std::uint32_t> groupSensors(std::uint64_t group) {
    std::vector<std::uint32_t> sensors;
    for (std::uint32_t i = 0; i < 64; ++i) {
        if ((group >> i) & 1u) sensors.push_back(i);
    }
    return sensors;
}

}  // namespace verve::core
