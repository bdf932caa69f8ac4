#include "core/observation_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/action_branches.hpp"
#include "verve/error.hpp"

namespace verve::core {
namespace {

[[noreturn]] void refuse(const std::string& message) { throw Error(ErrorCode::InvalidArgument, message); }

}  // namespace

void checkFinite(float value, const char* what) {
    if (!std::isfinite(value)) refuse(std::string(what) + " must be finite, got " + std::to_string(value));
}

void checkTimeStep(float dt) {
    if (!std::isfinite(dt) || dt <= 0.0f) refuse("dt must be a finite number > 0, got " + std::to_string(dt));
}

void checkActionMask(const AgentDescriptor& desc, const std::uint8_t* allowed, std::size_t count) {
    if (allowed == nullptr) refuse("the action mask is NULL");
    const ActionBranches branches = ActionBranches::of(desc);
    if (count != branches.columns) {
        refuse("the action mask has " + std::to_string(count) + " flags, the agent has " + std::to_string(branches.columns) +
               (branches.count == 1 ? " actions" : " choices in its action branches"));
    }
    for (std::size_t a = 0; a < count; ++a) {
        if (allowed[a] > 1) refuse("action mask flag " + std::to_string(a) + " must be 0 or 1, got " + std::to_string(allowed[a]));
    }
    for (std::uint32_t b = 0; b < branches.count; ++b) {
        const std::uint8_t* flags = allowed + branches.offset[b];
        if (std::find(flags, flags + branches.size[b], std::uint8_t{1}) != flags + branches.size[b]) continue;
        refuse(branches.count == 1 ? std::string("the action mask allows no action (at least one flag must be 1)")
                                   : "the action mask allows no choice of branch " + std::to_string(b) +
                                         " (at least one of its flags must be 1)");
    }
}

void checkDemonstratedContinuous(const AgentDescriptor& desc, const float* values, std::uint32_t count) {
    if (count != desc.continuousActions) {
        refuse("the demonstrated continuous action has " + std::to_string(count) + " values, the agent has " +
               std::to_string(desc.continuousActions) + " continuous actions");
    }
    if (count > 0 && values == nullptr) refuse("the demonstrated continuous action's values are missing (null)");
    for (std::uint32_t d = 0; d < count; ++d) {
        // Written so that NaN fails too.
        if (!(values[d] >= -1.0f && values[d] <= 1.0f)) {
            refuse("the demonstrated continuous action " + std::to_string(d) + " is " + std::to_string(values[d]) +
                   ": each must be within [-1, 1]");
        }
    }
}

void checkDemonstratedAction(const AgentDescriptor& desc, std::uint32_t action, const std::uint8_t* allowed) {
    if (action >= desc.numActions) {
        refuse("the demonstrated action " + std::to_string(action) + " is out of range (the agent has " +
               std::to_string(desc.numActions) + " actions)");
    }
    if (allowed == nullptr) return;
    std::uint32_t column[ActionBranches::kMax];
    const ActionBranches branches = ActionBranches::of(desc);
    for (std::uint32_t b = 0, n = branches.columnsOf(action, column); b < n; ++b) {
        if (allowed[column[b]] == 0) {
            refuse("the demonstrated action " + std::to_string(action) + " is one the action mask forbids" +
                   (branches.count == 1 ? std::string() : " (branch " + std::to_string(b) + ")"));
        }
    }
}

void checkObservation(const AgentDescriptor& desc, ObservationView obs) {
    const auto nd = desc.discreteSensors.size();
    const auto nc = desc.continuousSensors.size();
    if (obs.numDiscrete != nd) {
        refuse("observation has " + std::to_string(obs.numDiscrete) + " discrete values, the agent has " +
               std::to_string(nd) + " discrete sensors");
    }
    if (obs.numContinuous != nc) {
        refuse("observation has " + std::to_string(obs.numContinuous) + " continuous values, the agent has " +
               std::to_string(nc) + " continuous sensors");
    }
    if ((nd > 0 && obs.discrete == nullptr) || (nc > 0 && obs.continuous == nullptr)) {
        refuse("observation values are NULL");
    }
    for (std::size_t i = 0; i < nd; ++i) {
        const std::int32_t v = obs.discrete[i];
        if (v < 0 || static_cast<std::uint32_t>(v) >= desc.discreteSensors[i]) {
            refuse("discrete sensor " + std::to_string(i) + " reads " + std::to_string(v) + ", valid values are 0.." +
                   std::to_string(desc.discreteSensors[i] - 1));
        }
    }
    for (std::size_t i = 0; i < nc; ++i) {
        const float v = obs.continuous[i];
        if (!std::isfinite(v)) refuse("continuous sensor " + std::to_string(i) + " reads " + std::to_string(v) + ", values must be finite");
    }
}

void normalizeObservation(const std::uint8_t* circular, ObservationView obs, std::vector<float>& normalized) {
    normalized.resize(obs.numContinuous);
    for (std::size_t i = 0; i < obs.numContinuous; ++i) {
        float v = obs.continuous[i];
        if (circular[i] != 0) {
            v = std::fmod(v + 1.0f, 2.0f);  // wrap into [-1, 1)
            if (v < 0.0f) v += 2.0f;
            v -= 1.0f;
        } else {
            v = std::clamp(v, -1.0f, 1.0f);
        }
        normalized[i] = v;
    }
}

}  // namespace verve::core
