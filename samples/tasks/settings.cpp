#include "tasks/settings.hpp"

#include <map>
#include <stdexcept>

namespace verve::tasks {

AgentDescriptor atLibraryDefaults(const AgentDescriptor& task) {
    AgentDescriptor d;
    d.discreteSensors = task.discreteSensors;
    d.continuousSensors = task.continuousSensors;
    d.grouping = task.grouping;  // which sensors belong together describes the sensors
    d.sensorGroups = task.sensorGroups;
    d.numActions = task.numActions;
    d.actionBranches = task.actionBranches;  // how the actions are made up describes the actions
    d.continuousActions = task.continuousActions;
    d.seed = task.seed;
    d.planning = task.planning;
    d.curiosity = task.curiosity;
    return d;
}

void applySetting(AgentDescriptor& d, const std::string& setting) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("a setting is key=value, not " + setting);
    const std::string key = setting.substr(0, eq);
    double v = 0.0;
    try {
        v = std::stod(setting.substr(eq + 1));
    } catch (const std::exception&) {
        throw std::invalid_argument("the setting " + key + " wants a number, not " + setting.substr(eq + 1));
    }
    const std::map<std::string, float AgentDescriptor::*> floats{
        {"tau_value", &AgentDescriptor::tauValue},
        {"tau_discount", &AgentDescriptor::tauDiscount},
        {"tau_eligibility", &AgentDescriptor::tauEligibility},
        {"policy_multiplier", &AgentDescriptor::policyMultiplier},
        {"policy_weight_bound", &AgentDescriptor::policyWeightBound},
        {"trace_threshold", &AgentDescriptor::traceThreshold},
        {"tau_model", &AgentDescriptor::tauModel}};
    if (auto f = floats.find(key); f != floats.end()) {
        d.*(f->second) = static_cast<float>(v);
    } else if (key == "resolution") {
        d.resolution = static_cast<std::uint32_t>(v);
    } else if (key == "planning") {
        d.planning = v != 0.0;
    } else if (key == "adaptation") {
        d.adaptation = static_cast<std::uint32_t>(v);
    } else if (key == "sensor_grouping" && (v == 0.0 || v == 1.0)) {  // auto or joint; custom needs a list
        d.grouping = static_cast<SensorGrouping>(static_cast<int>(v));
    } else if (key == "max_planning_steps") {
        d.maxPlanningSteps = static_cast<std::uint32_t>(v);
    } else {
        throw std::invalid_argument("unknown setting " + key);
    }
}

}  // namespace verve::tasks
