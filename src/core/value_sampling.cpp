// Value-function images (thesis figures 19, 23, 36): V over one or two swept sensors.
#include <string>

#include "core/agent_impl.hpp"
#include "core/observation_check.hpp"

namespace verve {
namespace {

[[noreturn]] void refuse(const std::string& message) { throw Error(ErrorCode::InvalidArgument, message); }

void checkAxis(const AgentDescriptor& desc, const ValueAxis& axis) {
    if (axis.kind == SensorKind::Discrete) {
        if (axis.index >= desc.discreteSensors.size()) refuse("value axis names discrete sensor " + std::to_string(axis.index) + ", which does not exist");
        if (axis.samples != desc.discreteSensors[axis.index]) {
            refuse("a discrete value axis needs samples = the sensor's value count (" +
                   std::to_string(desc.discreteSensors[axis.index]) + ")");
        }
    } else if (axis.kind == SensorKind::Continuous) {
        if (axis.index >= desc.continuousSensors.size()) refuse("value axis names continuous sensor " + std::to_string(axis.index) + ", which does not exist");
        if (axis.samples < 2) refuse("a continuous value axis needs at least 2 samples");
    } else {
        refuse("value axis kind must be Discrete or Continuous");
    }
}

}  // namespace

void Agent::sampleValueFunction(const std::vector<ValueAxis>& axes, const Observation& base, float* out,
                                std::size_t outCount) const {
    const Impl& s = *impl_;
    if (axes.empty() || axes.size() > 2) refuse("sample the value function over 1 or 2 axes");
    for (const auto& axis : axes) checkAxis(s.desc, axis);
    if (axes.size() == 2 && axes[0].kind == axes[1].kind && axes[0].index == axes[1].index) refuse("the two value axes name the same sensor");
    const std::size_t n0 = axes[0].samples;
    const std::size_t n1 = axes.size() == 2 ? axes[1].samples : 1;
    if (out == nullptr) refuse("output buffer is NULL");
    if (outCount < n0 * n1) refuse("output buffer holds " + std::to_string(outCount) + " values, " + std::to_string(n0 * n1) + " are needed");

    Observation obs = base;
    std::vector<float> normalized;
    core::checkObservation(s.desc, obs.view());
    core::normalizeObservation(s.rep.circular(), obs.view(), normalized);
    obs.continuous = normalized;
    auto set = [&obs](const ValueAxis& axis, std::size_t i) {
        if (axis.kind == SensorKind::Discrete) obs.discrete[axis.index] = static_cast<std::int32_t>(i);
        else obs.continuous[axis.index] = -1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(axis.samples - 1);
    };
    std::vector<core::ActiveFeature> phi;
    const core::ValueBounds bounds = s.constantsFor(s.lastDt).values;  // as stats.value and TD errors see V
    for (std::size_t i1 = 0; i1 < n1; ++i1) {
        if (axes.size() == 2) set(axes[1], i1);
        for (std::size_t i0 = 0; i0 < n0; ++i0) {
            set(axes[0], i0);
            s.rep.find(obs.discrete.data(), obs.continuous.data(), phi);
            out[i1 * n0 + i0] = core::bounded(s.td.value(s.weights, phi), bounds);
        }
    }
}

}  // namespace verve
