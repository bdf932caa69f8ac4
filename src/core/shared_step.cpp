// A batch's bodies of one brain, updated on several threads at once (docs/crowds.md, "Bodies in
// parallel"). Agent::Impl::step split in three: prepareShared acts and computes the TD error of a
// body against the brain as the batch found it, and writes nothing to the brain; commitShared
// adds the rewards and TD errors it saw to the brain's measures, in body order; between the two
// and finishShared, TdLearner::trainPart applies each body's weight changes, part by part of the
// features, each weight taking the bodies' changes in body order. The result depends on the bodies'
// order only, never on the number of threads. A step that would change the brain in any other way
// (a new RBF, the model and its plans) is not prepared: the batch makes it whole afterwards.
#include <limits>
#include <utility>

#include "core/agent_impl.hpp"
#include "core/observation_check.hpp"

namespace verve {

bool Agent::Impl::prepareShared(float reward, ObservationView obs, float dt, core::LookupScratch& scratch,
                                std::uint32_t parts) {
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
    s.sharedStep = SharedStep{};
    const float r = s.clampedReward(reward);
    s.sharedStep.seesReward = s.learning && s.hasPrevious;
    s.sharedStep.reward = r;
    s.lastDt = dt;
    if (s.learning) s.trialSeconds += dt;

    // The brain's reward range as a single update would see it: with this reward in it.
    core::RewardRange rewards = s.brain->rewards;
    if (s.sharedStep.seesReward) rewards.see(r);
    const StepConstants k = s.constantsFor(dt, rewards);
    if (s.learning && s.hasPrevious && s.learnsFromRealSteps()) {
        const float before = s.td.value(s.weights, s.previous, s.ahead);
        const float next = core::bounded(s.td.value(s.weights, s.current, s.ahead), k.values);
        const float delta = r + k.gamma * next - core::bounded(before, k.values);
        s.td.stage(delta, k.rates, k.traceDecay, parts);
        s.sharedStep.seesDelta = k.traceDecay > 0.0f;  // as learnReal
        s.sharedStep.delta = delta;
        s.stats.tdError = delta;
    }
    const bool samples = s.selection == ActionSelection::Sample;
    const float hopeless = s.learning && samples ? core::hopelessValue(k.values) : -std::numeric_limits<float>::infinity();
    // Its own learning step counts, as in a single update (acting before it halved the food an
    // arena's shared brain found, docs/crowds.md); the other bodies' steps reach the brain later.
    const std::uint32_t action = s.td.chooseActionStaged(s.weights, s.current, s.rng, s.probabilities, s.latestValue,
                                                         !samples, hopeless);
    s.stats.value = core::bounded(s.latestValue, k.values);
    s.recordProbabilities(nullptr, s.latestValue <= hopeless);
    s.sharedStep.marks = s.learning && s.learnsFromRealSteps();  // finishShared, once the traces have decayed
    if (s.teacher.armed()) s.teacher.remember(dt, action, s.current);

    std::swap(s.previous, s.current);
    s.previousAction = action;
    s.previousDiscrete.assign(obs.discrete, obs.discrete + obs.numDiscrete);
    std::swap(s.previousContinuous, s.normalized);
    s.hasPrevious = true;
    ++s.stats.steps;
    s.stats.rbfCount = s.rep.featureCount();
    return true;
}

void Agent::Impl::commitShared() {
    if (sharedStep.seesReward) brain->rewards.see(sharedStep.reward);
    if (sharedStep.seesDelta) brain->tdScale.see(sharedStep.delta);
}

void Agent::Impl::finishShared() {
    td.finishStaged();
    if (sharedStep.marks) td.mark(previous, previousAction, rep.featureCount());
    stats.liveTraces = td.liveCount();
    sharedStep = SharedStep{};
}

}  // namespace verve
