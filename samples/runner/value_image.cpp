#include "value_image.hpp"

namespace verve::demo {

namespace {

ValueAxisInfo continuousAxis(std::uint32_t index, std::uint32_t samples, const std::vector<std::string>& names) {
    ValueAxisInfo info{{SensorKind::Continuous, index, samples},
                       index < names.size() ? names[index] : "continuous sensor " + std::to_string(index),
                       {}};
    for (std::uint32_t i = 0; i < samples; ++i) info.coordinates.push_back(-1.0 + 2.0 * i / (samples - 1));
    return info;
}

ValueAxisInfo discreteAxis(std::uint32_t index, std::uint32_t values) {
    ValueAxisInfo info{{SensorKind::Discrete, index, values}, "discrete sensor " + std::to_string(index), {}};
    for (std::uint32_t i = 0; i < values; ++i) info.coordinates.push_back(i);
    return info;
}

}  // namespace

std::optional<ValueImage> sampleValueImage(const Agent& agent, const std::vector<std::string>& sensorNames,
                                           std::uint32_t continuousSamples) {
    const AgentDescriptor& d = agent.descriptor();
    const auto numC = static_cast<std::uint32_t>(d.continuousSensors.size());
    const auto numD = static_cast<std::uint32_t>(d.discreteSensors.size());
    ValueImage image;
    if (numC >= 2) {
        image.axes = {continuousAxis(numC - 2, continuousSamples, sensorNames),
                      continuousAxis(numC - 1, continuousSamples, sensorNames)};
    } else if (numC == 1) {
        image.axes = {continuousAxis(0, continuousSamples, sensorNames)};
        if (numD >= 1) image.axes.push_back(discreteAxis(0, d.discreteSensors[0]));
    } else if (numD >= 1) {
        image.axes = {discreteAxis(0, d.discreteSensors[0])};
        if (numD >= 2) image.axes.push_back(discreteAxis(1, d.discreteSensors[1]));
    } else {
        return std::nullopt;
    }
    std::vector<ValueAxis> axes;
    std::size_t count = 1;
    for (const ValueAxisInfo& a : image.axes) {
        axes.push_back(a.axis);
        count *= a.axis.samples;
    }
    image.values.assign(count, 0.0f);
    agent.sampleValueFunction(axes, Observation(d), image.values.data(), image.values.size());
    return image;
}

}  // namespace verve::demo
