// Which sensor groups matter: a step size per lattice, learned from the TD errors
// (docs/algorithm.md, "Which sensors matter"; Adaptation::GroupRates). With many sensors the agent
// sums a lattice per group of them (core/sensor_groups.hpp), and the rates divide by every group's
// activations: with six distractors beside a position and its signal, the groups that matter took
// a seventh of each step and the signaled plate 18.5 steps a trial where 9.5 are possible.
//
// Each lattice's step is scaled by e^(log rate), kept in proportion so that the step over all
// lattices stays what it was (their mean, weighted by their activations, is 1): what one group
// gains, the others give. A log rate follows Sutton's IDBD (1992) as Autostep (Mahmood et al.
// 2012) normalises it: it rises while the TD error keeps pushing the lattice's weights the way
// they recently moved (delta * sum e_i h_i > 0, h_i the recent change of critic weight i) and falls
// when it pushes them back. The scale enters through the traces (mark() takes each activation
// times its lattice's scale), so every learning kernel stays as it is and the actor's steps follow
// the critic's. Agents of one lattice, or of a lattice and those beside it, are left alone.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/active_feature.hpp"
#include "core/state_representation.hpp"
#include "verve/agent_descriptor.hpp"

namespace verve::core {

class TdLearner;

class GroupRates {
public:
    static constexpr float kMetaRate = 0.01f;      // a log rate's largest change per step
    static constexpr float kNormAveraging = 0.01f;  // how fast the normaliser forgets a large gradient
    static constexpr float kLogLimit = 6.0f;        // log rates stay within +-this
    static constexpr float kHistoryLimit = 1e6f;    // |h_i| (and a step's |delta|) at most

    // Active for a descriptor with Adaptation::GroupRates whose sensors form two or more groups.
    static bool appliesTo(const AgentDescriptor& d);
    GroupRates(const AgentDescriptor& d, const StateRepresentation& rep);

    bool active() const { return active_; }
    // The largest value trace a scale allows: the scale of a lattice that takes the whole step
    // (every other log rate at its floor and this one at its ceiling is less); 1 without.
    float traceLimit(const StateRepresentation& rep) const;
    // Room for `features` features' history (before anything changes), then their history at 0.
    void reserve(std::uint32_t features);
    void grow(std::uint32_t features);

    // phi with each activation times its lattice's scale, into `out` (reserved to phi's size).
    void scale(const StateRepresentation& rep, const std::vector<ActiveFeature>& phi, std::vector<ActiveFeature>& out) const;

    // One real step of TD error `delta` at critic rate `eta`, before the traces decay: the
    // gradient, the log rates, then the history.
    void learn(const StateRepresentation& rep, const TdLearner& td, float delta, float eta);
    // The same in parts, for a batch's bodies of one brain (core/shared_step.cpp): each body's
    // gradient against the brain as the batch found it (its live traces, in their order), then,
    // in body order, the rates and the history from the traces the body kept.
    void gradient(const StateRepresentation& rep, const TdLearner& td, float delta, float* out) const;
    void apply(const StateRepresentation& rep, const float* gradient);
    void remember(const std::uint32_t* features, const float* rows, std::size_t count, std::uint32_t stride, float delta,
                  float eta);
    std::size_t lattices() const { return logRates_.size(); }
    float scaleOf(std::size_t lattice) const { return scales_[lattice]; }

    // Saved state (AgentSnapshot::groupLogRates, groupNorms, groupHistory).
    const std::vector<float>& logRates() const { return logRates_; }
    const std::vector<float>& norms() const { return norms_; }
    const std::vector<float>& history() const { return history_; }
    // Restores them (validated: one log rate and norm per lattice, one history value per feature).
    void restore(const StateRepresentation& rep, const std::vector<float>& logRates, const std::vector<float>& norms,
                 const std::vector<float>& history);

private:
    // Scales from the log rates, weighted by the lattices' expected activation sums.
    void rescale(const StateRepresentation& rep);
    // A step's TD error within +-kHistoryLimit, as the gradient and the history take it.
    static float boundedDelta(float delta) { return std::clamp(delta, -kHistoryLimit, kHistoryLimit); }
    // f(feature, e) for every live feature with a history (e its value trace), and the gradient
    // of the step's TD error (`bounded`: boundedDelta's) from them into `out`, one per lattice.
    template <typename F>
    void sweep(const StateRepresentation& rep, const TdLearner& td, float bounded, float* out, F&& f) const;
    // h = h (1 - eta e)+ + eta delta e: the critic weight's recent change, decaying as IDBD's does.
    void rememberOne(std::uint32_t feature, float e, float delta, float eta);

    bool active_ = false;
    std::vector<float> logRates_;
    std::vector<float> norms_;       // Autostep's v: a decaying maximum of |gradient|
    std::vector<float> scales_;      // e^(log rate), normalised
    std::vector<float> history_;     // h per feature
};

}  // namespace verve::core
