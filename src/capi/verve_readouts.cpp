// Read-outs: value, TD error, RBF count, statistics, value-function images.
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "capi/capi_agent.hpp"

using verve::capi::AgentUse;
using verve::capi::guarded;
using verve::capi::requireArg;

namespace {

verve::ValueAxis toAxis(const verve_value_axis& axis, uint32_t i) {
    if (axis.kind != VERVE_SENSOR_DISCRETE && axis.kind != VERVE_SENSOR_CONTINUOUS) {
        throw verve::Error(verve::ErrorCode::InvalidArgument,
                           "axes[" + std::to_string(i) + "].kind must be VERVE_SENSOR_DISCRETE or VERVE_SENSOR_CONTINUOUS");
    }
    verve::ValueAxis out;
    out.kind = axis.kind == VERVE_SENSOR_DISCRETE ? verve::SensorKind::Discrete : verve::SensorKind::Continuous;
    out.index = axis.index;
    out.samples = axis.samples;
    return out;
}

void requireCount(uint32_t count, std::size_t expected, const char* name, const char* what) {
    if (count != expected) {
        throw verve::Error(verve::ErrorCode::InvalidArgument, std::string(name) + " is " + std::to_string(count) +
                                                                  ", the agent has " + std::to_string(expected) + " " + what);
    }
}

}  // namespace

extern "C" {

VERVE_API verve_result VERVE_CALL verve_agent_get_value(const verve_agent* agent, float* out_value) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(out_value, "out_value");
        *out_value = a.valueEstimate();
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_get_td_error(const verve_agent* agent, float* out_td_error) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(out_td_error, "out_td_error");
        *out_td_error = a.tdError();
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_get_action_probabilities(const verve_agent* agent, float* out,
                                                                      uint32_t count) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(out, "out");
        const std::vector<float>& p = a.actionProbabilities();
        if (count != p.size()) {
            throw verve::Error(verve::ErrorCode::InvalidArgument, "count is " + std::to_string(count) +
                                                                      ", the agent has " + std::to_string(p.size()) + " actions");
        }
        std::copy(p.begin(), p.end(), out);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_get_continuous_action(const verve_agent* agent, float* out, uint32_t count) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        requireArg(out, "out");
        const std::vector<float>& v = use.agent().continuousAction();
        if (count != v.size()) {
            throw verve::Error(verve::ErrorCode::InvalidArgument, "count is " + std::to_string(count) + ", the agent has " +
                                                                      std::to_string(v.size()) + " continuous actions");
        }
        std::copy(v.begin(), v.end(), out);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_get_rbf_count(const verve_agent* agent, uint32_t* out_count) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(out_count, "out_count");
        *out_count = static_cast<uint32_t>(a.rbfCount());
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_get_stats(const verve_agent* agent, verve_agent_stats* out) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(out, "out");
        const uint32_t size = out->struct_size;
        if (size != VERVE_AGENT_STATS_SIZE_V1 && size != VERVE_AGENT_STATS_SIZE_V2) {
            throw verve::Error(verve::ErrorCode::InvalidArgument,
                               "out->struct_size is " + std::to_string(size) + ", expected sizeof(verve_agent_stats) = " +
                                   std::to_string(VERVE_AGENT_STATS_SIZE_V2) + " (or " +
                                   std::to_string(VERVE_AGENT_STATS_SIZE_V1) + " from an older header)");
        }
        const verve::AgentStats s = a.stats();
        verve_agent_stats full{};
        full.struct_size = size;
        full.steps = s.steps;
        full.rbf_count = s.rbfCount;
        full.live_traces = s.liveTraces;
        full.value = s.value;
        full.td_error = s.tdError;
        full.model_error = s.modelError;
        full.predicted_uncertainty = s.predictedUncertainty;
        full.planning_steps = s.planningSteps;
        full.curiosity_reward = s.curiosityReward;
        full.rbf_budget_hits = s.rbfBudgetHits;
        full.clamped_rewards = s.clampedRewards;
        std::memcpy(out, &full, size);  // an older, smaller struct gets only its own bytes
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_sample_values(const verve_agent* agent, const verve_value_axis* axes,
                                                            uint32_t n_axes, const int32_t* base_discrete,
                                                            uint32_t n_discrete, const float* base_continuous,
                                                            uint32_t n_continuous, float* out, uint32_t out_count) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(axes, "axes");
        requireArg(out, "out");
        if (n_discrete > 0) requireArg(base_discrete, "base_discrete (with n_discrete > 0)");
        if (n_continuous > 0) requireArg(base_continuous, "base_continuous (with n_continuous > 0)");
        // The counts first: the base arrays are only as long as the host says.
        requireCount(n_discrete, a.descriptor().discreteSensors.size(), "n_discrete", "discrete sensors");
        requireCount(n_continuous, a.descriptor().continuousSensors.size(), "n_continuous", "continuous sensors");
        if (n_axes < 1 || n_axes > 2) {
            throw verve::Error(verve::ErrorCode::InvalidArgument, "n_axes must be 1 or 2, not " + std::to_string(n_axes));
        }
        std::vector<verve::ValueAxis> swept;
        for (uint32_t i = 0; i < n_axes; ++i) swept.push_back(toAxis(axes[i], i));
        verve::Observation base;
        base.discrete.assign(base_discrete, base_discrete + n_discrete);
        base.continuous.assign(base_continuous, base_continuous + n_continuous);
        a.sampleValueFunction(swept, base, out, out_count);
    });
}

}  // extern "C"
