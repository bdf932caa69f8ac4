// XML text -> AgentSnapshot: every element and attribute checked, every problem named.
#include <pugixml.hpp>

#include <algorithm>
#include <string_view>

#include "io/number_text.hpp"
#include "io/snapshot_check.hpp"
#include "io/snapshot_xml.hpp"
#include "io/xml_memory.hpp"
#include "verve/error.hpp"

namespace verve::io {
namespace {

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCode::Format, message); }

std::string where(pugi::xml_node node) { return std::string("<") + node.name() + ">"; }

pugi::xml_node child(pugi::xml_node parent, const char* name) {
    pugi::xml_node n = parent.child(name);
    if (!n) fail("missing <" + std::string(name) + "> in " + where(parent));
    return n;
}

std::string_view attributeText(pugi::xml_node node, const char* name) {
    pugi::xml_attribute a = node.attribute(name);
    if (!a) fail("missing attribute '" + std::string(name) + "' of " + where(node));
    return a.value();
}

[[noreturn]] void failAttribute(pugi::xml_node node, const char* name, std::string_view text, const char* expected) {
    fail(where(node) + " attribute '" + name + "': '" + std::string(text.substr(0, 40)) + "' is not " + expected);
}

float readFloat(pugi::xml_node node, const char* name) {
    const std::string_view text = attributeText(node, name);
    float v = 0.0f;
    if (!parseNumber(text, v)) failAttribute(node, name, text, "a number");
    return v;
}

std::uint64_t readUint64(pugi::xml_node node, const char* name) {
    const std::string_view text = attributeText(node, name);
    std::uint64_t v = 0;
    if (!parseNumber(text, v)) failAttribute(node, name, text, "a non-negative integer");
    return v;
}

std::uint32_t readUint32(pugi::xml_node node, const char* name) {
    const std::uint64_t v = readUint64(node, name);
    if (v > UINT32_MAX) failAttribute(node, name, attributeText(node, name), "a 32-bit integer");
    return static_cast<std::uint32_t>(v);
}

bool readBool(pugi::xml_node node, const char* name) {
    const std::string_view text = attributeText(node, name);
    if (text == "true") return true;
    if (text == "false") return false;
    failAttribute(node, name, text, "true or false");
}

template <typename T>
std::vector<T> readList(pugi::xml_node node, const std::string& label) {
    std::vector<T> values;
    std::string bad;
    if (!parseList(node.text().get(), values, bad)) fail(label + " holds '" + bad + "', which is not a valid number");
    return values;
}

template <typename T>
std::vector<T> readChildList(pugi::xml_node parent, const char* name) {
    return readList<T>(child(parent, name), where(parent) + " <" + name + ">");
}

void readCount(pugi::xml_node node, std::size_t listed, const char* what) {
    const std::uint64_t count = readUint64(node, "count");
    if (count != listed) {
        fail(where(node) + " says count=" + std::to_string(count) + " but lists " + std::to_string(listed) + " " +
             what + " (truncated or edited?)");
    }
}

AgentDescriptor readDescriptor(pugi::xml_node root) {
    pugi::xml_node n = child(root, "descriptor");
    AgentDescriptor d;
    d.resolution = readUint32(n, "resolution");
    d.numActions = readUint32(n, "actions");
    const std::string_view allocation = attributeText(n, "allocation");
    if (allocation == "dynamic") d.allocation = RbfAllocation::Dynamic;
    else if (allocation == "full") d.allocation = RbfAllocation::Full;
    else failAttribute(n, "allocation", allocation, "dynamic or full");
    d.tauValue = readFloat(n, "tau_value");
    d.tauDiscount = readFloat(n, "tau_discount");
    d.tauEligibility = readFloat(n, "tau_eligibility");
    d.policyMultiplier = readFloat(n, "policy_multiplier");
    d.traceThreshold = readFloat(n, "trace_threshold");
    if (n.attribute("policy_weight_bound")) d.policyWeightBound = readFloat(n, "policy_weight_bound");  // absent: 0
    // Absent from saves made before adaptation: they keep every setting as given.
    d.adaptation = n.attribute("adaptation") ? readUint32(n, "adaptation") : 0u;
    d.seed = readUint64(n, "seed");
    d.planning = readBool(n, "planning");
    d.tauModel = readFloat(n, "tau_model");
    d.maxPlanningSteps = readUint32(n, "max_planning_steps");
    d.planningUncertaintyThreshold = readFloat(n, "planning_uncertainty_threshold");
    const std::string_view curiosity = attributeText(n, "curiosity");
    if (curiosity == "none") d.curiosity = CuriosityMode::None;
    else if (curiosity == "novelty") d.curiosity = CuriosityMode::Novelty;
    else if (curiosity == "progress") d.curiosity = CuriosityMode::Progress;
    else failAttribute(n, "curiosity", curiosity, "none, novelty or progress");
    d.curiosityFactor = readFloat(n, "curiosity_factor");
    d.planningAccumulatesUncertainty = readBool(n, "planning_accumulates_uncertainty");
    d.learnFromRealSteps = readBool(n, "learn_from_real_steps");
    const std::string_view prediction = attributeText(n, "discrete_prediction");
    if (prediction == "categorical") d.discretePrediction = DiscretePrediction::Categorical;
    else if (prediction == "ordinal") d.discretePrediction = DiscretePrediction::Ordinal;
    else failAttribute(n, "discrete_prediction", prediction, "categorical or ordinal");
    // Absent from saves made before the RBF budget: they get the default budget.
    if (n.attribute("max_rbfs")) d.maxRbfs = readUint64(n, "max_rbfs");
    for (pugi::xml_node s : n.children("discrete_sensor")) d.discreteSensors.push_back(readUint32(s, "values"));
    for (pugi::xml_node s : n.children("continuous_sensor")) d.continuousSensors.push_back({readBool(s, "circular")});
    if (n.attribute("grouping")) {
        const std::string_view grouping = attributeText(n, "grouping");
        if (grouping == "joint") d.grouping = SensorGrouping::Joint;
        else if (grouping == "custom") d.grouping = SensorGrouping::Custom;
        else failAttribute(n, "grouping", grouping, "joint or custom");
    } else {
        d.grouping = legacyGrouping(d);
    }
    for (pugi::xml_node s : n.children("sensor_group")) d.sensorGroups.push_back(readUint64(s, "sensors"));
    for (pugi::xml_node b : n.children("action_branch")) d.actionBranches.push_back(readUint32(b, "choices"));
    if (n.attribute("continuous_actions")) d.continuousActions = readUint32(n, "continuous_actions");
    return d;
}

void readState(pugi::xml_node root, AgentSnapshot& s) {
    pugi::xml_node n = child(root, "state");
    s.learning = readBool(n, "learning");
    s.steps = readUint64(n, "steps");
    s.modelError = readFloat(n, "model_error");
    s.lastDt = readFloat(n, "last_dt");
    if (n.attribute("reward_low")) s.rewardLow = readFloat(n, "reward_low");  // absent: the snapshot's [-1, 1]
    if (n.attribute("reward_high")) s.rewardHigh = readFloat(n, "reward_high");
    // absent: a save from before final rewards were counted apart, [0, 0]
    if (n.attribute("final_reward_low")) s.finalRewardLow = readFloat(n, "final_reward_low");
    if (n.attribute("final_reward_high")) s.finalRewardHigh = readFloat(n, "final_reward_high");
    if (n.attribute("continuous_model")) {  // absent: an older save (0.1.0 among them), whose model predicts positions
        const std::string_view model = attributeText(n, "continuous_model");
        if (model == "change") s.modelPredictsChange = true;
        else if (model != "position") failAttribute(n, "continuous_model", model, "change or position");
    }
    // Absent from saves made before adaptation: nothing measured yet.
    if (n.attribute("horizon_trial_seconds")) s.horizonTrialSeconds = readFloat(n, "horizon_trial_seconds");
    if (n.attribute("horizon_trials")) s.horizonTrials = readUint32(n, "horizon_trials");
    if (n.attribute("td_mean_square")) s.tdMeanSquare = readFloat(n, "td_mean_square");
    std::vector<std::uint64_t> rng;
    std::string bad;
    if (!parseList(attributeText(n, "rng"), rng, bad) || rng.size() != s.rng.size()) {
        failAttribute(n, "rng", attributeText(n, "rng"), "four 64-bit integers");
    }
    std::copy(rng.begin(), rng.end(), s.rng.begin());
}

void readFeatures(pugi::xml_node root, AgentSnapshot& s) {
    pugi::xml_node f = child(root, "features");
    s.featureKeys = readChildList<std::uint64_t>(f, "keys");
    readCount(f, s.featureKeys.size(), "keys");
    s.centres = readChildList<float>(f, "centres");
    pugi::xml_node w = child(root, "weights");
    s.stride = readUint32(w, "stride");
    s.weights = readList<float>(w, "<weights>");
    if (pugi::xml_node g = root.child("group_rates")) {
        s.groupLogRates = readChildList<float>(g, "log_rates");
        s.groupNorms = readChildList<float>(g, "norms");
        s.groupHistory = readChildList<float>(g, "history");
    }
}

void readShortTermMemory(pugi::xml_node root, AgentSnapshot& s) {
    if (pugi::xml_node t = root.child("traces")) {
        s.traceStride = readUint32(t, "stride");
        s.traceFeatures = readChildList<std::uint32_t>(t, "features");
        readCount(t, s.traceFeatures.size(), "features");
        s.traces = readChildList<float>(t, "values");
        if (t.attribute("trial_seconds")) s.trialSeconds = readFloat(t, "trial_seconds");  // absent before 0.3
        // Absent before the horizon followed the rewards: the whole trial one stretch.
        s.stretchSeconds = t.attribute("stretch_seconds") ? readFloat(t, "stretch_seconds") : s.trialSeconds;
        if (t.attribute("stretch_longest")) s.stretchLongest = readFloat(t, "stretch_longest");
        if (t.attribute("stretch_reward")) s.stretchReward = readFloat(t, "stretch_reward");
        if (t.attribute("stretch_seen")) s.stretchSeen = readBool(t, "stretch_seen");
    }
    if (pugi::xml_node c = root.child("continuous_actions")) {
        s.continuousNoiseRunning = readBool(c, "noise_running");
        s.continuousValues = readChildList<float>(c, "values");
        s.continuousNoise = readChildList<float>(c, "noise");
    }
    pugi::xml_node p = root.child("previous");
    s.hasPrevious = static_cast<bool>(p);
    if (!p) return;
    s.previousAction = readUint32(p, "action");
    s.previousFeatures = readChildList<std::uint32_t>(p, "features");
    s.previousActivations = readChildList<float>(p, "activations");
    s.previousDiscrete = readChildList<std::int32_t>(p, "discrete");
    s.previousContinuous = readChildList<float>(p, "continuous");
}

std::size_t lineOf(const char* data, std::size_t size, std::ptrdiff_t offset) {
    const auto end = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, std::min<std::ptrdiff_t>(offset, std::ptrdiff_t(size))));
    return 1 + static_cast<std::size_t>(std::count(data, data + end, '\n'));
}

pugi::xml_node parseRoot(pugi::xml_document& doc, const char* data, std::size_t size) {
    if (size == 0) fail("the save is empty");
    const pugi::xml_parse_result parsed = doc.load_buffer(data, size, pugi::parse_default, pugi::encoding_utf8);
    throwIfXmlRanOutOfMemory();  // not a corrupt save: std::bad_alloc, VERVE_ERROR_OUT_OF_MEMORY
    if (!parsed) {
        std::string message = std::string("not well-formed XML at line ") +
                               std::to_string(lineOf(data, size, parsed.offset)) + ": " + parsed.description();
        if (static_cast<std::size_t>(parsed.offset) + 1 >= size) message += " (the save ends early: truncated?)";
        fail(message);
    }
    pugi::xml_node root = doc.document_element();
    if (std::string_view(root.name()) != kRootElement) {
        fail("not a Verve agent save: the root element is <" + std::string(root.name()) + ">, expected <" + kRootElement + ">");
    }
    return root;
}

void checkVersion(pugi::xml_node root) {
    const std::uint64_t version = readUint64(root, "format_version");
    if (version == 0) fail("format_version 0 is not a valid version");
    if (version > AgentSnapshot::kFormatVersion) {
        throw Error(ErrorCode::Version, "the save has format version " + std::to_string(version) +
                                            "; this library reads up to version " +
                                            std::to_string(AgentSnapshot::kFormatVersion) + " (update Verve)");
    }
}

}  // namespace

AgentSnapshot snapshotFromXml(const char* data, std::size_t size) {
    if (data == nullptr) throw Error(ErrorCode::InvalidArgument, "no data (NULL pointer)");
    pugi::xml_document doc;
    pugi::xml_node root = parseRoot(doc, data, size);
    checkVersion(root);
    AgentSnapshot s;
    s.descriptor = readDescriptor(root);
    readState(root, s);
    readFeatures(root, s);
    readShortTermMemory(root, s);
    checkSnapshot(s);
    return s;
}

}  // namespace verve::io
