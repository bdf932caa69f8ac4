#include "core/group_rates.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/sensor_groups.hpp"
#include "core/td_learner.hpp"

namespace verve::core {

bool GroupRates::appliesTo(const AgentDescriptor& d) {
    return (d.adaptation & Adaptation::GroupRates) != 0 && sensorGroups(d).size() > 1;
}

GroupRates::GroupRates(const AgentDescriptor& d, const StateRepresentation& rep) : active_(appliesTo(d)) {
    if (!active_) return;
    const std::size_t n = rep.groupCount();
    logRates_.assign(n, 0.0f);
    norms_.assign(n, 0.0f);
    scales_.assign(n, 1.0f);
    history_.assign(rep.featureCount(), 0.0f);
}

float GroupRates::traceLimit(const StateRepresentation& rep) const {
    if (!active_) return 1.0f;
    float total = 0.0f, least = rep.latticeSum(0);
    for (std::size_t k = 0; k < lattices(); ++k) {
        total += rep.latticeSum(k);
        least = std::min(least, rep.latticeSum(k));
    }
    return total / least * (1.0f + 1e-5f);  // the float rounding of a scale
}

void GroupRates::reserve(std::uint32_t features) {
    if (active_) reserveRoom(history_, features);
}

void GroupRates::grow(std::uint32_t features) {
    if (active_ && features > history_.size()) history_.resize(features, 0.0f);
}

void GroupRates::scale(const StateRepresentation& rep, const std::vector<ActiveFeature>& phi,
                       std::vector<ActiveFeature>& out) const {
    out.resize(phi.size());
    for (std::size_t i = 0; i < phi.size(); ++i) {
        out[i] = ActiveFeature(phi[i].index, phi[i].activation * scales_[rep.latticeOf(phi[i].index)]);
    }
}

template <typename F>
void GroupRates::sweep(const StateRepresentation& rep, const TdLearner& td, float bounded, float* out, F&& f) const {
    std::fill(out, out + lattices(), 0.0f);
    const std::uint32_t* live = td.live();
    const float* traces = td.traces();
    const std::size_t stride = td.traceStride();
    for (std::uint32_t j = 0; j < td.liveCount(); ++j) {
        const std::uint32_t feature = live[j];
        if (feature >= history_.size()) continue;  // made since the history last grew: none yet
        const float e = traces[std::size_t(feature) * stride];
        out[rep.latticeOf(feature)] += e * history_[feature];
        f(feature, e);
    }
    for (std::size_t k = 0; k < lattices(); ++k) out[k] *= bounded;
}

void GroupRates::gradient(const StateRepresentation& rep, const TdLearner& td, float delta, float* out) const {
    sweep(rep, td, boundedDelta(delta), out, [](std::uint32_t, float) {});
}

void GroupRates::apply(const StateRepresentation& rep, const float* gradient) {
    for (std::size_t k = 0; k < logRates_.size(); ++k) {
        const float g = std::isfinite(gradient[k]) ? gradient[k] : 0.0f;
        const float size = std::fabs(g);
        norms_[k] = std::max(size, norms_[k] + kNormAveraging * (size - norms_[k]));
        if (norms_[k] > 0.0f) logRates_[k] = std::clamp(logRates_[k] + kMetaRate * g / norms_[k], -kLogLimit, kLogLimit);
    }
    rescale(rep);
}

void GroupRates::rescale(const StateRepresentation& rep) {
    // Scales in proportion to e^(log rate), their activation-weighted mean 1.
    float weighted = 0.0f, total = 0.0f;
    for (std::size_t k = 0; k < logRates_.size(); ++k) {
        scales_[k] = std::exp(logRates_[k]);
        weighted += scales_[k] * rep.latticeSum(k);
        total += rep.latticeSum(k);
    }
    const float norm = weighted > 0.0f ? total / weighted : 1.0f;
    for (float& scale : scales_) scale *= norm;
}

void GroupRates::rememberOne(std::uint32_t feature, float e, float delta, float eta) {
    float& h = history_[feature];
    h = std::clamp(h * std::max(0.0f, 1.0f - eta * e) + eta * delta * e, -kHistoryLimit, kHistoryLimit);
}

void GroupRates::remember(const std::uint32_t* features, const float* rows, std::size_t count, std::uint32_t stride,
                          float delta, float eta) {
    const float d = boundedDelta(delta);
    for (std::size_t j = 0; j < count; ++j) {
        if (features[j] < history_.size()) rememberOne(features[j], rows[j * stride], d, eta);
    }
}

void GroupRates::learn(const StateRepresentation& rep, const TdLearner& td, float delta, float eta) {
    if (!active_) return;
    // One pass: each live feature's part of the gradient reads its history before the step's change.
    std::array<float, DescriptorLimits::kMaxSensorGroups> g;
    const float d = boundedDelta(delta);
    sweep(rep, td, d, g.data(), [&](std::uint32_t feature, float e) { rememberOne(feature, e, d, eta); });
    apply(rep, g.data());
}

void GroupRates::restore(const StateRepresentation& rep, const std::vector<float>& logRates, const std::vector<float>& norms,
                         const std::vector<float>& history) {
    logRates_ = logRates;
    norms_ = norms;
    history_ = history;
    rescale(rep);
}

}  // namespace verve::core
