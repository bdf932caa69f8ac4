#include "core/predictive_model.hpp"

#include <algorithm>
#include <cmath>

#include "core/action_branches.hpp"

namespace verve::core {
namespace {

constexpr float kErrorLimit = 1e3f;  // applyDeltaRule's clamp on an output's error
// The two error averages behind learning progress learn at these fractions of eta_pred: the fast
// one follows recent errors, the slow one remembers older ones; noise moves both alike.
constexpr float kFastFraction = 0.5f;
constexpr float kSlowFraction = 0.05f;
constexpr std::uint32_t kScalarOutputs = 5;  // reward, terminal, certainty, fast, slow

std::uint64_t discreteOutputsFor(const AgentDescriptor& desc) {
    if (desc.discretePrediction == DiscretePrediction::Ordinal) return desc.discreteSensors.size();
    std::uint64_t n = 0;
    for (auto c : desc.discreteSensors) n += c;
    return n;
}

float ordinalTarget(std::int32_t value, std::uint32_t count) {
    return count > 1 ? -1.0f + 2.0f * static_cast<float>(value) / static_cast<float>(count - 1) : 0.0f;
}

// The shorter way round on a circular sensor (as the state representation measures distance).
float wrapDifference(float diff) {
    if (diff > 1.0f) return diff - 2.0f;
    if (diff < -1.0f) return diff + 2.0f;
    return diff;
}

// Into [-1, 1) in constant time whatever the magnitude: fmod (exact) first brings a large value
// into (-2, 2), where subtracting 2 in a loop would never end for |v| >= 2^25 (v - 2 == v).
// A non-finite output is no position at all: the centre.
float wrapInto(float v) {
    if (!std::isfinite(v)) return 0.0f;
    if (std::fabs(v) >= 3.0f) v = std::fmod(v, 2.0f);
    while (v >= 1.0f) v -= 2.0f;
    while (v < -1.0f) v += 2.0f;
    return v;
}

// A raw output as a finite number: huge (but finite) weights can sum to infinity or NaN.
float finite(float v) { return std::isfinite(v) ? v : 0.0f; }

}  // namespace

PredictiveModel::PredictiveModel(const AgentDescriptor& desc)
    : discreteCounts_(desc.discreteSensors),
      categorical_(desc.discretePrediction == DiscretePrediction::Categorical),
      tau_(desc.tauModel),
      activationSum_(std::pow(2.5f, static_cast<float>(desc.continuousSensors.size()))),
      invSigma2_(0.25f * static_cast<float>(desc.resolution) * static_cast<float>(desc.resolution)),
      base_(WeightLayout::kPolicy + ActionBranches::of(desc).columns),
      numContinuous_(static_cast<std::uint32_t>(desc.continuousSensors.size())),
      discreteOutputs_(desc.planning ? static_cast<std::uint32_t>(discreteOutputsFor(desc)) : 0) {
    for (const auto& s : desc.continuousSensors) circular_.push_back(s.circular);
    reward_ = numContinuous_ + discreteOutputs_;
    terminal_ = reward_ + 1;
    certainty_ = reward_ + 2;
    fast_ = reward_ + 3;
    slow_ = reward_ + 4;
    block_ = numContinuous_ + discreteOutputs_ + kScalarOutputs;
    if (!desc.planning) return;  // no scratch: a model that never runs costs nothing per discrete value
    outputs_.assign(block_, 0.0f);
    targets_.assign(block_, 0.0f);
    trained_.assign(block_, 0);
}

std::uint64_t PredictiveModel::outputsPerAction(const AgentDescriptor& desc) {
    return desc.continuousSensors.size() + discreteOutputsFor(desc) + kScalarOutputs;
}

std::uint32_t PredictiveModel::columnsFor(const AgentDescriptor& desc) {
    return desc.planning ? static_cast<std::uint32_t>(desc.numActions * outputsPerAction(desc)) : 0;
}

float PredictiveModel::rate(float dt) const {
    const float r = tau_ > 0.0f ? 1.0f - std::exp(-dt / tau_) : 1.0f;
    return r / activationSum_;
}

void PredictiveModel::rawOutputs(const WeightTable& w, const std::vector<ActiveFeature>& phi,
                                 std::uint32_t action) const {
    std::fill(outputs_.begin(), outputs_.end(), 0.0f);
    const std::uint32_t offset = base_ + action * block_;
    float total = 0.0f, trained = 0.0f;
    for (const auto& f : phi) {
        const float* row = w.row(f.index) + offset;
        for (std::uint32_t j = 0; j < block_; ++j) outputs_[j] += row[j] * f.activation;
        total += f.activation;
        if (row[certainty_] != 0.0f) trained += f.activation;
    }
    // A feature this action never trained (its certainty weight is still exactly 0) knows nothing:
    // the certainty counts only the share of the state that trained ones cover, so the confident
    // neighbours of a new state do not make it look known.
    if (total > 0.0f) outputs_[certainty_] *= trained / total;
}

void PredictiveModel::predict(const WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action,
                              const float* from, Prediction& out) const {
    rawOutputs(w, phi, action);
    out.continuous.resize(numContinuous_);
    for (std::uint32_t d = 0; d < numContinuous_; ++d) {
        const float v = outputs_[d] + (from != nullptr ? from[d] : 0.0f);
        out.continuous[d] = circular_[d] ? wrapInto(v) : std::clamp(finite(v), -1.0f, 1.0f);
    }
    out.discrete.resize(discreteCounts_.size());
    std::uint32_t column = numContinuous_;
    for (std::size_t i = 0; i < discreteCounts_.size(); ++i) {
        const std::uint32_t count = discreteCounts_[i];
        if (categorical_) {
            std::uint32_t best = 0;
            for (std::uint32_t v = 1; v < count; ++v) {
                if (outputs_[column + v] > outputs_[column + best]) best = v;
            }
            out.discrete[i] = static_cast<std::int32_t>(best);
            column += count;
        } else {
            const float scaled = (std::clamp(finite(outputs_[column]), -1.0f, 1.0f) + 1.0f) * 0.5f * static_cast<float>(count - 1);
            out.discrete[i] = static_cast<std::int32_t>(std::lround(scaled));
            column += 1;
        }
    }
    out.reward = std::clamp(outputs_[reward_], -1.0f, 1.0f);
    out.terminal = std::clamp(outputs_[terminal_], 0.0f, 1.0f);
    out.uncertainty = std::clamp(1.0f - outputs_[certainty_], 0.0f, 1.0f);
    const float fastError = std::clamp(1.0f - outputs_[fast_], 0.0f, 1.0f);
    const float slowError = std::clamp(1.0f - outputs_[slow_], 0.0f, 1.0f);
    out.progress = slowError - fastError;
}

// Targets for one transition (discrete == nullptr: terminal, no next observation; from: see train). Returns the
// normalised squared error of the current outputs: each predicted quantity contributes one term
// in [0, 1], and the terms are averaged. A continuous value one RBF width (sigma) off counts as
// wholly wrong, as it would land on other features; a wrong discrete value counts 1, and the
// reward's full range counts 1.
float PredictiveModel::fillTargets(const float* from, const std::int32_t* discrete, const float* continuous, float reward,
                                   bool terminal) {
    std::fill(trained_.begin(), trained_.end(), std::uint8_t{0});
    lastUncertainty_ = std::clamp(1.0f - outputs_[certainty_], 0.0f, 1.0f);
    float sum = 0.0f;
    std::uint32_t terms = 0;
    if (!terminal) {
        for (std::uint32_t d = 0; d < numContinuous_; ++d) {
            float diff = continuous[d] - (outputs_[d] + (from != nullptr ? from[d] : 0.0f));
            if (circular_[d]) diff = wrapDifference(diff);
            targets_[d] = outputs_[d] + diff;
            trained_[d] = 1;
            sum += std::min(1.0f, diff * diff * invSigma2_);
            ++terms;
        }
        std::uint32_t column = numContinuous_;
        for (std::size_t i = 0; i < discreteCounts_.size(); ++i) {
            const std::uint32_t count = discreteCounts_[i];
            if (categorical_) {
                float e = 0.0f;
                for (std::uint32_t v = 0; v < count; ++v) {
                    const float t = static_cast<std::int32_t>(v) == discrete[i] ? 1.0f : 0.0f;
                    targets_[column + v] = t;
                    trained_[column + v] = 1;
                    e += (t - outputs_[column + v]) * (t - outputs_[column + v]);
                }
                sum += std::min(1.0f, 0.5f * e);  // a confident wrong value counts 1
                column += count;
            } else {
                const float t = ordinalTarget(discrete[i], count);
                targets_[column] = t;
                trained_[column] = 1;
                sum += std::min(1.0f, 0.25f * (t - outputs_[column]) * (t - outputs_[column]));
                column += 1;
            }
            ++terms;
        }
    }
    targets_[reward_] = reward;
    targets_[terminal_] = terminal ? 1.0f : 0.0f;
    trained_[reward_] = trained_[terminal_] = 1;
    const float re = reward - outputs_[reward_];
    const float te = targets_[terminal_] - outputs_[terminal_];
    sum += std::min(1.0f, 0.25f * re * re) + std::min(1.0f, te * te);
    terms += 2;
    const float error = sum / static_cast<float>(terms);
    // The error estimators learn toward 1 - error (zero weights mean fully uncertain).
    targets_[certainty_] = targets_[fast_] = targets_[slow_] = 1.0f - error;
    trained_[certainty_] = trained_[fast_] = trained_[slow_] = 1;
    return error;
}

void PredictiveModel::applyDeltaRule(WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action,
                                     float rate) {
    // One error per output, shared by every active feature: w += eta (d - y) x. Targets lie in
    // [-1, 1] and a learned model's outputs near them; an error beyond kErrorLimit comes only from
    // weights a hostile save brought (up to AgentSnapshot::kWeightLimit), and clamped, its steps
    // stay below the float spacing at that limit: one update cannot overflow a weight to inf.
    for (std::uint32_t j = 0; j < block_; ++j) {
        targets_[j] = trained_[j] ? std::clamp(targets_[j] - outputs_[j], -kErrorLimit, kErrorLimit) : 0.0f;
    }
    const float fastRate = rate * kFastFraction;
    const float slowRate = rate * kSlowFraction;
    const std::uint32_t offset = base_ + action * block_;
    for (const auto& f : phi) {
        float* row = w.row(f.index) + offset;
        const float step = rate * f.activation;
        for (std::uint32_t j = 0; j < fast_; ++j) row[j] += step * targets_[j];
        row[fast_] += fastRate * f.activation * targets_[fast_];
        row[slow_] += slowRate * f.activation * targets_[slow_];
    }
}

float PredictiveModel::train(WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action,
                             const float* from, const std::int32_t* discrete, const float* continuous, float reward, float rate) {
    rawOutputs(w, phi, action);
    const float error = fillTargets(from, discrete, continuous, reward, false);
    applyDeltaRule(w, phi, action, rate);
    return error;
}

float PredictiveModel::trainTerminal(WeightTable& w, const std::vector<ActiveFeature>& phi, std::uint32_t action,
                                     float reward, float rate) {
    rawOutputs(w, phi, action);
    const float error = fillTargets(nullptr, nullptr, nullptr, reward, true);
    applyDeltaRule(w, phi, action, rate);
    return error;
}

}  // namespace verve::core
