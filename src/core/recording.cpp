// verve::Recording: demonstrations kept for replay (include/verve/recording.hpp). Every entry is
// checked as the agent would check it, when it is added (and when a file is loaded), so a replay
// cannot be refused part-way.
#include "verve/recording.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "core/observation_check.hpp"
#include "core/weight_table.hpp"
#include "verve/error.hpp"

namespace verve {
namespace {

[[noreturn]] void refuse(const std::string& message) { throw Error(ErrorCode::InvalidArgument, message); }

// The sensors and actions as an agent's descriptor, checked as an agent's is (AgentDescriptor::validate).
AgentDescriptor shapeOf(std::vector<std::uint32_t> discrete, std::uint32_t continuous, std::uint32_t actions,
                        std::uint32_t continuousActions) {
    // Bounded before anything is sized from it: a loaded file's count may be anything.
    if (continuous > DescriptorLimits::kMaxSensors) {
        refuse("a recording has at most " + std::to_string(DescriptorLimits::kMaxSensors) + " continuous sensors");
    }
    AgentDescriptor d;
    d.discreteSensors = std::move(discrete);
    d.continuousSensors.resize(continuous);
    // A lattice per sensor: the shape never builds a representation, and Auto's groups would refuse
    // more than 32 continuous sensors that an agent with Custom groups may have.
    d.grouping = SensorGrouping::Custom;
    for (std::uint32_t i = 0; i < continuous; ++i) d.sensorGroups.push_back(std::uint64_t(1) << i);
    d.numActions = actions;
    d.continuousActions = continuousActions;
    d.validate();
    return d;
}

}  // namespace

Recording::Recording(std::vector<std::uint32_t> discreteSensors, std::uint32_t continuousSensors, std::uint32_t numActions,
                     std::uint32_t continuousActions)
    : shape_(shapeOf(std::move(discreteSensors), continuousSensors, numActions, continuousActions)) {}

Recording Recording::shapedLike(const AgentDescriptor& desc) {
    return Recording(desc.discreteSensors, static_cast<std::uint32_t>(desc.continuousSensors.size()), desc.numActions,
                     desc.continuousActions);
}

void Recording::checkRoom() const {
    if (kinds_.size() >= kMaxEntries) {
        throw Error(ErrorCode::InvalidState, "the recording is full (" + std::to_string(kMaxEntries) + " entries): save it and start another");
    }
}

void Recording::addStep(float reward, ObservationView obs, float dt, std::uint32_t action) {
    addChecked(reward, obs, dt, action, nullptr);
}

void Recording::addStep(float reward, ObservationView obs, float dt, std::uint32_t action, ContinuousActionView continuousAction) {
    core::checkDemonstratedContinuous(shape_, continuousAction.values, continuousAction.count);
    addChecked(reward, obs, dt, action, continuousAction.count > 0 ? &continuousAction : nullptr);
}

void Recording::addChecked(float reward, ObservationView obs, float dt, std::uint32_t action,
                           const ContinuousActionView* continuousAction) {
    core::checkObservation(shape_, obs);
    core::checkFinite(reward, "reward");
    core::checkTimeStep(dt);
    core::checkDemonstratedAction(shape_, action, nullptr);
    checkRoom();
    // Room first: a failed allocation records nothing.
    const std::size_t nca = continuousAction != nullptr ? continuousAction->count : 0;
    core::reserveRoom(continuousActions_, continuousActions_.size() + nca);
    core::reserveRoom(kinds_, kinds_.size() + 1);
    core::reserveRoom(rewards_, rewards_.size() + 1);
    core::reserveRoom(dts_, dts_.size() + 1);
    core::reserveRoom(actions_, actions_.size() + 1);
    core::reserveRoom(discrete_, discrete_.size() + obs.numDiscrete);
    core::reserveRoom(continuous_, continuous_.size() + obs.numContinuous);
    kinds_.push_back(continuousAction != nullptr ? Kind::ContinuousStep : Kind::Step);
    if (nca > 0) continuousActions_.insert(continuousActions_.end(), continuousAction->values, continuousAction->values + nca);
    rewards_.push_back(reward);
    dts_.push_back(dt);
    actions_.push_back(action);
    discrete_.insert(discrete_.end(), obs.discrete, obs.discrete + obs.numDiscrete);
    continuous_.insert(continuous_.end(), obs.continuous, obs.continuous + obs.numContinuous);
}

void Recording::addEnd(Kind kind, float reward, const char* what) {
    core::checkFinite(reward, what);
    checkRoom();
    core::reserveRoom(kinds_, kinds_.size() + 1);
    core::reserveRoom(rewards_, rewards_.size() + 1);
    kinds_.push_back(kind);
    rewards_.push_back(reward);
}

void Recording::addEndEpisode(float finalReward) { addEnd(Kind::EndEpisode, finalReward, "final reward"); }

void Recording::addTruncation(float reward) { addEnd(Kind::Truncation, reward, "reward"); }

void Recording::replayInto(Agent& agent) const {
    const AgentDescriptor& d = agent.descriptor();
    if (d.discreteSensors != discreteSensors() || d.continuousSensors.size() != continuousSensors() || d.numActions != numActions()) {
        refuse("the recording's sensors and actions (" + std::to_string(discreteSensors().size()) + " discrete, " +
               std::to_string(continuousSensors()) + " continuous, " + std::to_string(numActions()) +
               " actions) are not the agent's (" + std::to_string(d.discreteSensors.size()) + ", " +
               std::to_string(d.continuousSensors.size()) + ", " + std::to_string(d.numActions) + ")");
    }
    const bool holdsContinuous = std::find(kinds_.begin(), kinds_.end(), Kind::ContinuousStep) != kinds_.end();
    if (holdsContinuous && d.continuousActions != continuousActions()) {
        refuse("the recording's steps hold " + std::to_string(continuousActions()) + " continuous actions, the agent has " +
               std::to_string(d.continuousActions));
    }
    const std::size_t nca = continuousActions();
    std::size_t continuousStep = 0;
    const std::size_t nd = discreteSensors().size();
    const std::size_t nc = continuousSensors();
    std::size_t step = 0;
    for (std::size_t i = 0; i < kinds_.size(); ++i) {
        if (kinds_[i] == Kind::EndEpisode) {
            agent.endEpisode(rewards_[i]);
        } else if (kinds_[i] == Kind::Truncation) {
            agent.truncateEpisode(rewards_[i]);
        } else {
            const ObservationView obs{nd ? discrete_.data() + step * nd : nullptr, nd,
                                      nc ? continuous_.data() + step * nc : nullptr, nc};
            if (kinds_[i] == Kind::ContinuousStep) {
                const ContinuousActionView values{nca ? continuousActions_.data() + continuousStep * nca : nullptr,
                                                  static_cast<std::uint32_t>(nca)};
                agent.updateDemonstrated(rewards_[i], obs, dts_[step], actions_[step], values);
                ++continuousStep;
            } else {
                agent.updateDemonstrated(rewards_[i], obs, dts_[step], actions_[step]);
            }
            ++step;
        }
    }
}

}  // namespace verve
