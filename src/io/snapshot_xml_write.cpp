// AgentSnapshot -> XML text (layout in snapshot_xml.hpp).
#include <pugixml.hpp>

#include <type_traits>
#include <utility>

#include "io/number_text.hpp"
#include "io/snapshot_check.hpp"
#include "io/snapshot_xml.hpp"
#include "io/xml_memory.hpp"
#include "verve/error.hpp"

namespace verve::io {
namespace {

struct StringWriter : pugi::xml_writer {
    std::string text;
    void write(const void* data, std::size_t size) override { text.append(static_cast<const char*>(data), size); }
};

// Values as text, `perLine` to a line, so a matrix reads as rows.
template <typename T>
std::string listText(const std::vector<T>& values, std::size_t perLine) {
    std::string out;
    out.reserve(values.size() * 12 + 2);
    if (perLine == 0) perLine = 16;
    for (std::size_t i = 0; i < values.size(); ++i) {
        out += (i % perLine == 0) ? '\n' : ' ';
        if constexpr (std::is_same_v<T, float>) {
            appendNumber(out, values[i]);
        } else if constexpr (std::is_signed_v<T>) {
            appendNumber(out, static_cast<std::int64_t>(values[i]));
        } else {
            appendNumber(out, static_cast<std::uint64_t>(values[i]));
        }
    }
    if (!values.empty()) out += '\n';
    return out;
}

void setNumber(pugi::xml_node node, const char* name, float value) {
    node.append_attribute(name).set_value(numberText(value).c_str());
}

void setNumber(pugi::xml_node node, const char* name, std::uint64_t value) {
    node.append_attribute(name).set_value(numberText(value).c_str());
}

template <typename T>
void appendList(pugi::xml_node parent, const char* name, const std::vector<T>& values, std::size_t perLine) {
    parent.append_child(name).text().set(listText(values, perLine).c_str());
}

const char* allocationName(RbfAllocation a) { return a == RbfAllocation::Full ? "full" : "dynamic"; }

const char* curiosityName(CuriosityMode c) {
    switch (c) {
        case CuriosityMode::Novelty: return "novelty";
        case CuriosityMode::Progress: return "progress";
        default: return "none";
    }
}

void writeDescriptor(pugi::xml_node root, const AgentDescriptor& d) {
    pugi::xml_node n = root.append_child("descriptor");
    setNumber(n, "resolution", std::uint64_t{d.resolution});
    setNumber(n, "actions", std::uint64_t{d.numActions});
    n.append_attribute("allocation").set_value(allocationName(d.allocation));
    setNumber(n, "tau_value", d.tauValue);
    setNumber(n, "tau_discount", d.tauDiscount);
    setNumber(n, "tau_eligibility", d.tauEligibility);
    setNumber(n, "policy_multiplier", d.policyMultiplier);
    setNumber(n, "trace_threshold", d.traceThreshold);
    // Written only when set, so saves of agents without it stay readable by older libraries.
    if (d.policyWeightBound > 0.0f) setNumber(n, "policy_weight_bound", d.policyWeightBound);
    setNumber(n, "adaptation", std::uint64_t{d.adaptation});
    setNumber(n, "seed", d.seed);
    n.append_attribute("planning").set_value(d.planning);
    setNumber(n, "tau_model", d.tauModel);
    setNumber(n, "max_planning_steps", std::uint64_t{d.maxPlanningSteps});
    setNumber(n, "planning_uncertainty_threshold", d.planningUncertaintyThreshold);
    n.append_attribute("curiosity").set_value(curiosityName(d.curiosity));
    setNumber(n, "curiosity_factor", d.curiosityFactor);
    n.append_attribute("planning_accumulates_uncertainty").set_value(d.planningAccumulatesUncertainty);
    setNumber(n, "max_rbfs", d.maxRbfs);
    n.append_attribute("learn_from_real_steps").set_value(d.learnFromRealSteps);
    n.append_attribute("discrete_prediction")
        .set_value(d.discretePrediction == DiscretePrediction::Ordinal ? "ordinal" : "categorical");
    for (auto values : d.discreteSensors) setNumber(n.append_child("discrete_sensor"), "values", std::uint64_t{values});
    for (const auto& c : d.continuousSensors) n.append_child("continuous_sensor").append_attribute("circular").set_value(c.circular);
    // Written only when not Auto, so saves of agents without groups stay readable by older libraries.
    if (d.grouping != SensorGrouping::Auto) {
        n.append_attribute("grouping").set_value(d.grouping == SensorGrouping::Joint ? "joint" : "custom");
    }
    for (auto g : d.sensorGroups) setNumber(n.append_child("sensor_group"), "sensors", g);
    for (auto b : d.actionBranches) setNumber(n.append_child("action_branch"), "choices", std::uint64_t{b});
    if (d.continuousActions != 0) setNumber(n, "continuous_actions", std::uint64_t{d.continuousActions});
}

void writeState(pugi::xml_node root, const AgentSnapshot& s) {
    pugi::xml_node n = root.append_child("state");
    n.append_attribute("learning").set_value(s.learning);
    setNumber(n, "steps", s.steps);
    setNumber(n, "model_error", s.modelError);
    setNumber(n, "last_dt", s.lastDt);
    setNumber(n, "reward_low", s.rewardLow);
    setNumber(n, "reward_high", s.rewardHigh);
    setNumber(n, "final_reward_low", s.finalRewardLow);
    setNumber(n, "final_reward_high", s.finalRewardHigh);
    n.append_attribute("continuous_model").set_value(s.modelPredictsChange ? "change" : "position");
    setNumber(n, "horizon_trial_seconds", s.horizonTrialSeconds);
    setNumber(n, "horizon_trials", std::uint64_t{s.horizonTrials});
    setNumber(n, "td_mean_square", s.tdMeanSquare);
    std::string rng;
    for (std::uint64_t word : s.rng) {
        if (!rng.empty()) rng += ' ';
        appendNumber(rng, word);
    }
    n.append_attribute("rng").set_value(rng.c_str());
}

void writeFeatures(pugi::xml_node root, const AgentSnapshot& s) {
    pugi::xml_node f = root.append_child("features");
    setNumber(f, "count", std::uint64_t{s.featureKeys.size()});
    appendList(f, "keys", s.featureKeys, 16);
    appendList(f, "centres", s.centres, s.descriptor.continuousSensors.size());
    pugi::xml_node w = root.append_child("weights");
    setNumber(w, "stride", std::uint64_t{s.stride});
    w.text().set(listText(s.weights, s.stride).c_str());
    if (!s.groupLogRates.empty() || !s.groupNorms.empty() || !s.groupHistory.empty()) {
        pugi::xml_node g = root.append_child("group_rates");
        appendList(g, "log_rates", s.groupLogRates, 16);
        appendList(g, "norms", s.groupNorms, 16);
        appendList(g, "history", s.groupHistory, 16);
    }
}

void writeShortTermMemory(pugi::xml_node root, const AgentSnapshot& s) {
    pugi::xml_node t = root.append_child("traces");
    setNumber(t, "stride", std::uint64_t{s.traceStride});
    setNumber(t, "count", std::uint64_t{s.traceFeatures.size()});
    appendList(t, "features", s.traceFeatures, 16);
    appendList(t, "values", s.traces, s.traceStride);
    setNumber(t, "trial_seconds", s.trialSeconds);
    setNumber(t, "stretch_seconds", s.stretchSeconds);
    setNumber(t, "stretch_longest", s.stretchLongest);
    setNumber(t, "stretch_reward", s.stretchReward);
    t.append_attribute("stretch_seen").set_value(s.stretchSeen);
    if (!s.continuousValues.empty() || !s.continuousNoise.empty()) {
        pugi::xml_node c = root.append_child("continuous_actions");
        c.append_attribute("noise_running").set_value(s.continuousNoiseRunning);
        appendList(c, "values", s.continuousValues, 16);
        appendList(c, "noise", s.continuousNoise, 16);
    }
    if (!s.hasPrevious) return;
    pugi::xml_node p = root.append_child("previous");
    setNumber(p, "action", std::uint64_t{s.previousAction});
    appendList(p, "features", s.previousFeatures, 16);
    appendList(p, "activations", s.previousActivations, 16);
    appendList(p, "discrete", s.previousDiscrete, 16);
    appendList(p, "continuous", s.previousContinuous, 16);
}

}  // namespace

std::string snapshotToXml(const AgentSnapshot& snapshot, bool includeTraces) {
    try {
        checkSnapshot(snapshot);
    } catch (const Error& e) {
        throw Error(ErrorCode::Internal, std::string("refusing to save an inconsistent agent: ") + e.what());
    }
    pugi::xml_document doc;
    pugi::xml_node root = doc.append_child(kRootElement);
    // The oldest version that has what the save holds: older libraries still read what they can,
    // and refuse what they would misread (groups, branches, continuous actions, group rates).
    const AgentDescriptor& d = snapshot.descriptor;
    const std::uint64_t version = !snapshot.groupLogRates.empty() ? 5u
                                  : d.continuousActions != 0      ? 4u
                                  : !d.actionBranches.empty()     ? 3u
                                  : !d.sensorGroups.empty()       ? 2u
                                                                  : 1u;
    setNumber(root, "format_version", version);
    writeDescriptor(root, snapshot.descriptor);
    writeState(root, snapshot);
    writeFeatures(root, snapshot);
    if (includeTraces) writeShortTermMemory(root, snapshot);
    // pugixml reports a failed allocation while building only by returning empty nodes.
    throwIfXmlRanOutOfMemory();
    StringWriter writer;
    doc.save(writer, "  ", pugi::format_indent, pugi::encoding_utf8);
    throwIfXmlRanOutOfMemory();
    return std::move(writer.text);
}

}  // namespace verve::io
