// A batch's bodies of one brain, updated on several threads at once (docs/crowds.md, "Bodies in
// parallel"). Agent::Impl::step split in three: prepareShared makes a body's step against the brain
// as the batch found it (its lookup, TD error, action and traces), keeping its weight changes
// (TdLearner::stage) instead of writing them; commitShared adds the rewards and TD errors it saw to
// the brain's measures, in body order; then TdLearner::trainPart applies the kept changes, part by
// part of the features, each weight taking the bodies' changes in body order. The result depends on
// the bodies' order only, never on the number of threads. A step that would change the brain in any
// other way (a new RBF, the model and its plans) is not prepared: the batch makes it whole afterwards.

#include "core/agent_impl.hpp"
#include "core/observation_check.hpp"

namespace verve {

bool Agent::Impl::prepareShared(float reward, ObservationView obs, float dt, core::LookupScratch& scratch,
                                std::uint32_t parts, SharedStep& seen) {
    Impl& s = *this;
    if (s.desc.planning) return false;  // the model and the plans train the brain as they go
    // The batch has checked the observation, the reward and dt. Everything that may allocate comes
    // before the first change, as in step(): a failure leaves the body as it was.
    core::normalizeObservation(s.rep.circular(), obs, s.normalized);
    s.rep.reserve(scratch, s.rep.featureCount());
    const bool covered = s.rep.find(obs.discrete, s.normalized.data(), s.current, scratch, s.ahead);
    // A new RBF (or a budget reached) is the brain's to make: the whole step comes later, in order.
    if (!covered && s.learning && s.desc.allocation == RbfAllocation::Dynamic) return false;
    s.reserveBody(s.rep.featureCount(), s.current.size());
    s.td.reserveStaged(parts);
    // Nothing below allocates.
    s.td.unstage();
    seen = SharedStep{};
    const float r = s.clampedReward(reward);
    seen.seesReward = s.learning && s.hasPrevious;
    seen.reward = r;
    s.lastDt = dt;
    if (s.learning) {
        s.trialSeconds += dt;
        s.stretch.see(s.hasPrevious, r, dt);
    }

    // The brain's reward range as a single update would see it: with this reward in it.
    core::RewardRange rewards = s.brain->rewards;
    if (seen.seesReward) rewards.see(r);
    const StepConstants k = s.constantsFor(dt, rewards);
    const bool learns = s.learning && s.hasPrevious && s.learnsFromRealSteps();
    if (learns) {
        const float delta = s.realTdError(r, k);
        s.td.stage(delta, k.rates);
        seen.seesDelta = k.traceDecay > 0.0f;  // as learnReal
        seen.learns = true;
        seen.delta = delta;
        seen.eta = k.rates.value;
        s.stats.tdError = delta;
        // The group rates' gradient against the brain as the batch found it; commitShared applies it.
        if (s.brain->groupRates.active()) s.brain->groupRates.gradient(s.rep, s.td, delta, s.groupGradient.data());
    }
    const bool samples = s.selection == ActionSelection::Sample;
    const float hopeless = s.hopelessFor(samples, k);
    // Its own learning step counts, as in a single update (single updates that acted before it found
    // a third of the food in the NPC arena, docs/crowds.md); the other bodies' steps reach the
    // brain later.
    const std::uint32_t action = s.td.chooseActionStaged(s.weights, s.current, s.rng, s.probabilities, s.latestValue,
                                                         !samples, hopeless);
    s.recordChoice(nullptr, hopeless, k);
    const float* gradients = s.actContinuous(!samples, dt, nullptr);
    // The traces are the body's own: kept as they were for the brain's change, they decay and take
    // the new step's at once.
    if (learns) s.td.keepAndDecay(k.traceDecay, parts);
    if (s.learning && s.learnsFromRealSteps()) s.markStep(action, gradients);
    s.endStep(obs, dt, action, gradients);
    return true;
}

void Agent::Impl::commitShared(BrainState& brain, const SharedStep& seen, const Impl& body) {
    if (seen.seesReward) brain.rewards.see(seen.reward);
    if (seen.seesDelta) brain.tdScale.see(seen.delta);
    if (seen.learns && brain.groupRates.active()) {
        // The rates, then the history from the traces the body kept as they were (their order by
        // part does not matter: each feature's history changes once).
        brain.groupRates.apply(brain.rep, body.groupGradient.data());
        brain.groupRates.remember(body.td.keptFeatures(), body.td.keptRows(), body.td.keptCount(), body.td.traceStride(),
                                  seen.delta, seen.eta);
    }
}

}  // namespace verve
