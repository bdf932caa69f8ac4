#include <cmath>
#include <string>

#include "verve/agent.hpp"

namespace verve {
namespace {

void require(bool ok, const std::string& message) {
    if (!ok) throw Error(ErrorCode::InvalidArgument, "invalid agent descriptor: " + message);
}

void requireTimeConstant(float tau, const char* name) {
    require(std::isfinite(tau) && tau >= 0.0f, std::string(name) + " must be a finite number >= 0");
}

}  // namespace

void AgentDescriptor::validate() const {
    require(numActions >= 1, "numActions must be at least 1");
    require(numActions <= 4096, "numActions must be at most 4096");
    require(discreteSensors.size() <= 16, "at most 16 discrete sensors");
    require(continuousSensors.size() <= 16, "at most 16 continuous sensors");
    double combinations = 1.0;
    for (std::size_t i = 0; i < discreteSensors.size(); ++i) {
        require(discreteSensors[i] >= 1,
                "discrete sensor " + std::to_string(i) + " must have at least 1 value");
        combinations *= discreteSensors[i];
    }
    require(combinations <= 9.0e15, "too many discrete value combinations (product of value counts)");
    if (!continuousSensors.empty()) {
        require(resolution >= 1 && resolution <= 4096, "resolution must be in [1, 4096]");
    }
    requireTimeConstant(tauValue, "tauValue");
    requireTimeConstant(tauDiscount, "tauDiscount");
    requireTimeConstant(tauEligibility, "tauEligibility");
    requireTimeConstant(tauModel, "tauModel");
    require(std::isfinite(policyMultiplier) && policyMultiplier >= 0.0f,
            "policyMultiplier must be a finite number >= 0");
    require(std::isfinite(traceThreshold) && traceThreshold > 0.0f && traceThreshold < 1.0f,
            "traceThreshold must be in (0, 1)");
    require(std::isfinite(policyWeightBound) && policyWeightBound >= 0.0f,
            "policyWeightBound must be a finite number >= 0 (0: unbounded)");
    require(allocation == RbfAllocation::Dynamic || allocation == RbfAllocation::Full,
            "allocation must be Dynamic or Full");
    require(maxPlanningSteps <= 100000, "maxPlanningSteps must be at most 100000");
    require(std::isfinite(planningUncertaintyThreshold) && planningUncertaintyThreshold >= 0.0f,
            "planningUncertaintyThreshold must be a finite number >= 0");
    require(curiosity == CuriosityMode::None || curiosity == CuriosityMode::Novelty ||
                curiosity == CuriosityMode::Progress,
            "curiosity must be None, Novelty or Progress");
    require(discretePrediction == DiscretePrediction::Categorical || discretePrediction == DiscretePrediction::Ordinal,
            "discretePrediction must be Categorical or Ordinal");
    require(std::isfinite(curiosityFactor) && curiosityFactor >= 0.0f,
            "curiosityFactor must be a finite number >= 0");
}

}  // namespace verve
