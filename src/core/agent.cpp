#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/agent_impl.hpp"
#include "core/continuous_demonstration.hpp"
#include "core/decision_rate.hpp"
#include "core/demonstration.hpp"
#include "core/observation_check.hpp"
#include "core/prefetch.hpp"
#include "core/warnings.hpp"

namespace verve {
namespace {

float rateFromTimeConstant(float dt, float tau) {
    return tau > 0.0f ? 1.0f - std::exp(-dt / tau) : 1.0f;  // tau 0: learn at once
}

float decayFromTimeConstant(float dt, float tau) { return tau > 0.0f ? std::exp(-dt / tau) : 0.0f; }

// One time constant in steps of dt, rounded (>= 1): rewards further ahead count less than 1/e.
std::uint32_t stepsWithinTimeConstant(float dt, float tau) {
    const double steps = static_cast<double>(tau) / static_cast<double>(dt);
    if (!(steps < 4e9)) return UINT32_MAX;  // no discount to speak of (or dt underflowing)
    return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(steps)));
}

}  // namespace

core::WeightLayout weightLayoutFor(const AgentDescriptor& desc) {
    core::WeightLayout layout;
    // The actor's columns: the discrete neurons, then each continuous action's mean and spread.
    layout.numActions = core::ActionBranches::of(desc).columns + 2 * desc.continuousActions;
    layout.modelColumns = core::PredictiveModel::columnsFor(desc);
    return layout;
}

BrainState::BrainState(const AgentDescriptor& d)
    : desc((d.validate(), d)), weights(weightLayoutFor(desc)), rep(desc), groupRates(desc, rep) {
    weights.resize(rep.featureCount());
}

Agent::Impl::Impl(const AgentDescriptor& d) : Impl(std::make_shared<BrainState>(d), d.seed) {}

Agent::Impl::Impl(std::shared_ptr<BrainState> shared, std::uint64_t seed)
    : brain(std::move(shared)),
      desc(brain->desc),
      rep(brain->rep),
      weights(brain->weights),
      rng(seed),
      td(core::ActionBranches::of(desc), 2 * desc.continuousActions, desc.traceThreshold),
      model(desc),
      planner(desc),
      continuous(desc.continuousActions) {
    previousDiscrete.assign(desc.discreteSensors.size(), 0);
    previousContinuous.assign(desc.continuousSensors.size(), 0.0f);
    normalized.reserve(desc.continuousSensors.size());
    probabilities.reserve(td.traceStride());  // chooseAction's scratch: one per trace component
    probabilities.assign(td.columns(), 0.0f);
    recordProbabilities(nullptr, true);  // uniform (in each branch)
    stats.rbfCount = rep.featureCount();
}

float Agent::Impl::tauDiscount(float dt) const {
    if ((desc.adaptation & Adaptation::Horizon) == 0) return desc.tauDiscount;
    return brain->horizon.tauDiscount(desc.tauDiscount, dt);
}

void Agent::Impl::endTrial() {
    // The horizon follows how far the rewards that matter lie: the trial's longest stretch of an
    // unchanged step reward (the whole trial with -1 a step until a goal; core/reward_stretch.hpp).
    if (learning) brain->horizon.seeTrial(stretch.trialLongest());
}

void Agent::Impl::markStep(std::uint32_t action, const float* gradients) {
    if (!brain->groupRates.active()) return td.mark(current, action, rep.featureCount(), gradients);
    // Each lattice's rate enters through its features' traces (core/group_rates.hpp).
    brain->groupRates.scale(rep, current, scaled);
    td.mark(scaled, action, rep.featureCount(), gradients);
}

void Agent::Impl::learnReal(float delta, const StepConstants& k, float decay) {
    // Before the traces decay: the rates learn from the traces this error credits.
    brain->groupRates.learn(rep, td, delta, k.rates.value);
    td.trainAndDecay(weights, delta, k.rates, decay, ahead);
    if (decay > 0.0f) brain->tdScale.see(delta);
    stats.tdError = delta;
}

StepConstants Agent::Impl::constantsFor(float dt) const { return constantsFor(dt, brain->rewards); }

StepConstants Agent::Impl::constantsFor(float dt, const core::RewardRange& rewards) const {
    StepConstants k;
    // Adaptation::DecisionRate: an update learns at least as much as a 0.1 s decision (core/decision_rate.hpp).
    const float seconds = (desc.adaptation & Adaptation::DecisionRate) != 0 ? core::DecisionRate::learningSeconds(dt) : dt;
    k.gamma = decayFromTimeConstant(dt, tauDiscount(dt));
    k.traceDecay = k.gamma * decayFromTimeConstant(seconds, desc.tauEligibility);
    k.rates.value = rateFromTimeConstant(seconds, desc.tauValue) / rep.activationSum();
    k.rates.policy = desc.policyMultiplier * k.rates.value;
    if ((desc.adaptation & Adaptation::ActorScale) != 0) k.rates.policy *= brain->tdScale.actorFactor();
    // Adaptation::HabitBound: with no bound of the user's, habits stay at or below +10 (core/habit_bound.hpp).
    k.rates.policyRange = core::PolicyRange::symmetric(desc.policyWeightBound);
    if (desc.policyWeightBound == 0.0f && (desc.adaptation & Adaptation::HabitBound) != 0) k.rates.policyRange = core::HabitBound::range();
    // Curiosity adds to the rewards of imagined steps: novelty up to its factor, progress (which
    // may be negative) up to its factor in size (core/curiosity.hpp).
    const float bonus = desc.planning && desc.curiosity != CuriosityMode::None ? desc.curiosityFactor : 0.0f;
    const float bonusLow = desc.curiosity == CuriosityMode::Progress ? -bonus : 0.0f;
    k.values = core::valueBounds(rewards, bonusLow, bonus, k.gamma);
    return k;
}

void Agent::Impl::learnModel(float reward, const std::int32_t* discrete, float dt) {
    const float* from = brain->modelPredictsChange ? previousContinuous.data() : nullptr;
    const float error = model.train(weights, previous, previousAction, from, discrete, normalized.data(), reward, model.rate(dt));
    recordModelError(error);
}

void Agent::Impl::learnModelTerminal(float reward) {
    recordModelError(model.trainTerminal(weights, previous, previousAction, reward, model.rate(lastDt)));
}

void Agent::Impl::recordModelError(float error) {
    stats.modelError += kModelErrorAveraging * (error - stats.modelError);
    stats.predictedUncertainty = model.lastUncertainty();
}

void Agent::Impl::plan(const StepConstants& k, const std::uint8_t* allowed) {
    core::PlanSettings p;
    p.maxSteps = desc.maxPlanningSteps;
    p.uncertaintyThreshold = desc.planningUncertaintyThreshold;
    p.accumulate = desc.planningAccumulatesUncertainty;
    p.curiosity = desc.curiosity;
    p.curiosityFactor = desc.curiosityFactor;
    p.gamma = k.gamma;
    p.traceDecay = k.traceDecay;
    p.rates = k.rates;
    p.values = k.values;
    p.rewards = brain->rewards;
    const bool curious = desc.curiosity != CuriosityMode::None;
    // Overlapping RBFs and no curiosity: plans teach only if they end within the discount horizon,
    // and the actor only at the real state, where it then weighs every action. Discrete features
    // and no curiosity: a first imagined step that stays at the real state is not replayed
    // (planner.hpp).
    p.onlyPlansThatEnd = !desc.continuousSensors.empty() && !curious;
    p.actorLearnsAtStartOnly = p.onlyPlansThatEnd;
    p.weighsEveryAction = p.onlyPlansThatEnd;
    p.allowed = allowed;
    if (p.onlyPlansThatEnd) p.maxSteps = std::min(p.maxSteps, stepsWithinTimeConstant(lastDt, tauDiscount(lastDt)));
    p.replaysNoStayAtStart = desc.continuousSensors.empty() && !curious;
    p.predictsChange = brain->modelPredictsChange;
    const core::PlanResult result = planner.run(p, current, normalized.data(), weights, rep, model, rng);
    stats.planningSteps = result.steps;
    stats.curiosityReward = result.curiosity;
}

namespace {

// One branch's probabilities from its n activations p (flags: its n mask flags or nullptr).
void normalizeBranch(float* p, std::uint32_t n, const std::uint8_t* flags, bool uniform) {
    float total = 0.0f;
    for (std::uint32_t a = 0; a < n; ++a) total += p[a];
    if (!uniform && total > 0.0f && std::isfinite(total)) {
        for (std::uint32_t a = 0; a < n; ++a) p[a] /= total;
        return;
    }
    // A hopeless state, or activations that were not finite: the choice was uniform among the allowed.
    float count = 0.0f;
    for (std::uint32_t a = 0; a < n; ++a) {
        p[a] = core::actionAllowed(flags, a) ? 1.0f : 0.0f;
        count += p[a];
    }
    for (std::uint32_t a = 0; a < n; ++a) p[a] /= count;
}

}  // namespace

void Agent::Impl::recordProbabilities(const std::uint8_t* allowed, bool uniform) {
    // One action set reads nothing of the (cold) branches.
    if (td.branchCount() == 1) return normalizeBranch(probabilities.data(), td.columns(), allowed, uniform);
    const core::ActionBranches& branches = td.branches();
    for (std::uint32_t b = 0; b < branches.count; ++b) {
        const std::uint8_t* flags = allowed == nullptr ? nullptr : allowed + branches.offset[b];
        normalizeBranch(probabilities.data() + branches.offset[b], branches.size[b], flags, uniform);
    }
}

void Agent::Impl::prefetch(unsigned stage) const noexcept {
    if (stage == 0) {
        // Every member before the planning state: what an update reads.
        core::prefetchBytes(this, static_cast<std::size_t>(reinterpret_cast<const char*>(&model) - reinterpret_cast<const char*>(this)));
    } else if (stage == 1) {
        core::prefetchBytes(brain.get(), sizeof(BrainState));
        core::prefetchData(previous);
        core::prefetchBytes(current.data(), current.capacity() * sizeof(core::ActiveFeature));
        core::prefetchData(previousContinuous);
        core::prefetchData(normalized);
        core::prefetchData(probabilities);
        td.prefetch();
    } else if (stage == 2) {
        core::prefetchData(weights.data());
        rep.prefetchLookup(0);
    } else {
        rep.prefetchLookup(stage - 2);
    }
}

void Agent::Impl::addArraysTo(core::PrefetchQueue& q, bool brainToo) const noexcept {
    if (brainToo) {
        rep.addArraysTo(q);
        q.add(weights.data().data(), weights.data().size() * sizeof(float));
    }
    td.addArraysTo(q);
}

void Agent::Impl::prefetchCheck(unsigned stage) const noexcept {
    if (stage == 0) {
        core::prefetchBytes(this, sizeof(brain) + sizeof(&desc));  // the first members
    } else {
        const auto* b = reinterpret_cast<const char*>(brain.get());
        core::prefetchBytes(b, static_cast<std::size_t>(reinterpret_cast<const char*>(&brain->desc + 1) - b));
    }
}

void Agent::Impl::reserveFor(std::uint32_t features, std::size_t active) {
    // The lookup has filled `current` already (allocating, if at all, before any change), and
    // `previous` only ever swaps buffers with it: scratch follows the neighbourhood, not the RBFs.
    rep.reserve(features);
    weights.reserve(features);
    brain->groupRates.reserve(features);
    reserveBody(features, active);
}

void Agent::Impl::reserveBody(std::uint32_t features, std::size_t active) {
    core::reserveRoom(current, active);
    if (brain->groupRates.active()) {
        core::reserveRoom(scaled, active);
        if (groupGradient.size() < brain->groupRates.lattices()) groupGradient.resize(brain->groupRates.lattices());
    }
    core::reserveRoom(probabilities, td.traceStride());  // a restore may have left it numActions
    td.reserve(features, active);
    if (desc.planning) planner.reserve(features);
    if (teacher.armed()) teacher.reserve(active, td.continuousColumns());
}

float Agent::Impl::learnedReward(float reward, bool final) {
    const float r = clampedReward(reward);
    if (learning && hasPrevious) {
        if (final) brain->rewards.seeFinal(r);
        else brain->rewards.see(r);
    }
    return r;
}

float Agent::Impl::clampedReward(float reward) {
    const float r = std::clamp(reward, -1.0f, 1.0f);
    if (r != reward) {
        ++stats.clampedRewards;
        if (!std::exchange(reportedClamp, true)) {
            core::warn("a reward of %g was clamped to [-1, 1] (rewards are expected in [-1, 1]; reported once per "
                       "agent, counted in stats.clamped_rewards)", static_cast<double>(reward));
        }
    }
    return r;
}

void Agent::Impl::noteBudgetReached() {
    ++stats.rbfBudgetHits;
    if (!std::exchange(reportedBudget, true)) {
        core::warn("the RBF budget (max_rbfs = %llu) is reached: no more RBFs are made, observations use the "
                   "existing ones within reach (reported once per agent, counted in stats.rbf_budget_hits)",
                   static_cast<unsigned long long>(desc.rbfBudget()));
    }
}

void Agent::Impl::resetShortTermMemory() {
    td.clear();
    continuous.resetNoise();
    hasPrevious = false;
    previous.clear();
    trialSeconds = 0.0f;
    stretch.reset();
    stats.liveTraces = 0;
}

Agent::Agent(const AgentDescriptor& descriptor) : impl_(std::make_unique<Impl>(descriptor)) {}
Agent::Agent(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Agent::~Agent() = default;
Agent::Agent(Agent&&) noexcept = default;
Agent& Agent::operator=(Agent&&) noexcept = default;

std::uint32_t Agent::update(float reward, const Observation& obs, float dt) { return update(reward, obs.view(), dt); }

std::uint32_t Agent::update(float reward, ObservationView obs, float dt) { return update(reward, obs, dt, ActionMask{}); }

std::uint32_t Agent::update(float reward, ObservationView obs, float dt, ActionMask mask) {
    return impl_->step(reward, obs, dt, mask, nullptr, nullptr);
}

void Agent::updateDemonstrated(float reward, ObservationView obs, float dt, std::uint32_t action, ActionMask mask) {
    impl_->step(reward, obs, dt, mask, &action, nullptr);
}

void Agent::updateDemonstrated(float reward, ObservationView obs, float dt, std::uint32_t action,
                               ContinuousActionView continuousAction, ActionMask mask) {
    core::checkDemonstratedContinuous(impl_->desc, continuousAction.values, continuousAction.count);
    impl_->step(reward, obs, dt, mask, &action, continuousAction.count > 0 ? continuousAction.values : nullptr);
}

std::uint32_t Agent::Impl::step(float reward, ObservationView obs, float dt, ActionMask mask,
                                const std::uint32_t* demonstrated, const float* demonstratedContinuous) {
    Impl& s = *this;
    // Everything is checked before anything changes (demonstratedContinuous by updateDemonstrated).
    if (mask.allowed != nullptr || mask.count != 0) core::checkActionMask(s.desc, mask.allowed, mask.count);
    if (demonstrated != nullptr) core::checkDemonstratedAction(s.desc, *demonstrated, mask.allowed);
    core::checkObservation(s.desc, obs);
    core::checkFinite(reward, "reward");
    core::checkTimeStep(dt);
    core::normalizeObservation(s.rep.circular(), obs, s.normalized);

    // Everything that may allocate, before anything changes (strong guarantee): the lookup, then
    // room for one more RBF everywhere, then the RBF itself (strong on its own).
    const bool covered = s.rep.find(obs.discrete, s.normalized.data(), s.current, s.ahead);
    bool grows = !covered && s.learning && s.desc.allocation == RbfAllocation::Dynamic;
    // One new RBF per group that has none within one width (one, for a single lattice).
    const std::uint32_t missing = grows ? s.rep.missing() : 0u;
    const bool overBudget = grows && std::uint64_t(s.rep.featureCount()) + missing > s.desc.rbfBudget();
    grows = grows && !overBudget;
    const std::uint32_t growth = grows ? missing : 0u;
    s.reserveFor(s.rep.featureCount() + growth, s.current.size() + growth);
    if (grows) {
        s.rep.addMissing(obs.discrete, s.normalized.data(), s.current);
        s.weights.resize(s.rep.featureCount());
        s.brain->groupRates.grow(s.rep.featureCount());
    }
    // Nothing below allocates.
    if (overBudget) s.noteBudgetReached();
    const float r = s.learnedReward(reward);
    s.lastDt = dt;
    if (s.learning) {
        s.trialSeconds += dt;
        s.stretch.see(s.hasPrevious, r, dt);
    }

    const bool plans = s.learning && s.desc.planning;
    const StepConstants k = s.constantsFor(dt);
    if (s.learning && s.hasPrevious) {
        if (plans) s.learnModel(r, obs.discrete, dt);
        if (s.learnsFromRealSteps()) {
            s.learnReal(s.realTdError(r, k), k, k.traceDecay);
        }
    }
    // Plan from the state just reached, before acting, so the action already uses what it taught.
    if (plans) s.plan(k, mask.allowed);

    // A demonstrated step draws nothing: what the policy would do is only read (probabilities, V).
    const bool samples = s.selection == ActionSelection::Sample && demonstrated == nullptr;
    const float hopeless = s.hopelessFor(samples, k);
    std::uint32_t action = s.td.chooseAction(s.weights, s.current, s.rng, s.probabilities, s.latestValue,
                                             mask.allowed, !samples, hopeless, s.ahead);
    s.recordChoice(mask.allowed, hopeless, k);
    // A demonstration without continuous values plays the continuous actions' means; with them, the
    // teacher's values stand for the agent's draws (core/continuous_demonstration.hpp).
    const float* gradients = s.actContinuous(!samples, dt, demonstratedContinuous);
    if (demonstrated != nullptr) {
        // The demonstrator's action stands for the agent's own (core/demonstration.hpp).
        action = *demonstrated;
        if (s.learning) {
            core::imitate(s.weights, s.current, action, s.td.branches(), mask.allowed, k.rates.policy, k.rates.policyRange);
            if (demonstratedContinuous != nullptr) {
                core::imitateContinuous(s.weights, s.current, s.td.columns(), s.td.continuousColumns(), gradients, k.rates.policy);
            }
        }
    }
    if (s.learning && s.learnsFromRealSteps()) s.markStep(action, gradients);
    s.endStep(obs, dt, action, gradients);
    return action;
}

const float* Agent::Impl::actContinuous(bool greedy, float dt, const float* demonstrated) {
    if (td.continuousColumns() == 0) return nullptr;
    const float* sums = probabilities.data() + td.columns();
    if (demonstrated != nullptr) continuous.play(sums, demonstrated);
    else continuous.act(sums, rng, dt, greedy);
    probabilities.resize(td.columns());
    return continuous.gradients();
}

float Agent::Impl::realTdError(float r, const StepConstants& k) const {
    // V(s) is the value the previous update left in latestValue: no weight changes between two
    // updates (endEpisode, resets and restores clear or recompute it), unless other bodies of a
    // shared brain trained it since.
    const float before = sharesBrain ? td.value(weights, previous, ahead) : latestValue;
    const float next = core::bounded(td.value(weights, current, ahead), k.values);
    return r + k.gamma * next - core::bounded(before, k.values);
}

float Agent::Impl::hopelessFor(bool samples, const StepConstants& k) const {
    // A learning agent that samples explores a state it values at the floor (core::hopelessValue); a
    // greedy or frozen one plays its policy.
    return learning && samples ? core::hopelessValue(k.values) : -std::numeric_limits<float>::infinity();
}

void Agent::Impl::recordChoice(const std::uint8_t* allowed, float hopeless, const StepConstants& k) {
    stats.value = core::bounded(latestValue, k.values);
    recordProbabilities(allowed, latestValue <= hopeless);
}

void Agent::Impl::endStep(ObservationView obs, float dt, std::uint32_t action, const float* gradients) {
    if (teacher.armed()) teacher.remember(dt, action, current, gradients);
    std::swap(previous, current);
    previousAction = action;
    previousDiscrete.assign(obs.discrete, obs.discrete + obs.numDiscrete);
    std::swap(previousContinuous, normalized);  // both hold numContinuous values: no copy
    hasPrevious = true;
    ++stats.steps;
    stats.rbfCount = rep.featureCount();
    stats.liveTraces = td.liveCount();
}

void Agent::endEpisode(float finalReward) {
    Impl& s = *impl_;
    core::checkFinite(finalReward, "final reward");
    const float r = s.learnedReward(finalReward, true);
    if (s.learning && s.hasPrevious && s.desc.planning) s.learnModelTerminal(r);
    if (s.learning && s.hasPrevious && s.learnsFromRealSteps()) {
        // Terminal: nothing lies beyond, so no value is bootstrapped (delta = r - V(s)).
        // The transition lasted as long as the step that chose its action: the last dt.
        const StepConstants k = s.constantsFor(s.lastDt);
        const float delta = r - core::bounded(s.td.value(s.weights, s.previous), k.values);
        s.learnReal(delta, k, 0.0f);
    }
    s.endTrial();
    s.resetShortTermMemory();
}

void Agent::truncateEpisode(float reward) {
    Impl& s = *impl_;
    core::checkFinite(reward, "reward");
    const float r = s.learnedReward(reward);
    if (s.learning && s.hasPrevious && s.learnsFromRealSteps()) {
        // Not terminal: the trial would have gone on from where the last action led, which the
        // agent never saw; the last state's value stands in for it: delta = r + gamma V(s) - V(s).
        const StepConstants k = s.constantsFor(s.lastDt);
        const float v = core::bounded(s.td.value(s.weights, s.previous), k.values);
        const float delta = r + k.gamma * v - v;
        s.learnReal(delta, k, 0.0f);
    }
    s.endTrial();
    s.resetShortTermMemory();
}

void Agent::teach(float praise) {
    Impl& s = *impl_;
    core::checkFinite(praise, "praise");
    if (praise < -1.0f || praise > 1.0f) {
        throw Error(ErrorCode::InvalidArgument, "praise must be within [-1, 1] (1: good, -1: bad), got " + std::to_string(praise));
    }
    if (s.learning && praise != 0.0f) {
        const StepConstants k = s.constantsFor(s.lastDt);
        s.teacher.credit(s.weights, praise, k.rates.policy, k.rates.policyRange, s.td.branches());
    }
    s.teacher.arm();  // after the credit: a refused or failed call changes nothing
}

void Agent::resetShortTermMemory() { impl_->resetShortTermMemory(); }

void Agent::setActionSelection(ActionSelection mode) {
    if (mode != ActionSelection::Sample && mode != ActionSelection::Greedy) {
        throw Error(ErrorCode::InvalidArgument, "action selection must be Sample or Greedy");
    }
    impl_->selection = mode;
}

ActionSelection Agent::actionSelection() const { return impl_->selection; }
const std::vector<float>& Agent::actionProbabilities() const { return impl_->probabilities; }
const std::vector<float>& Agent::continuousAction() const { return impl_->continuous.values(); }

void Agent::setLearning(bool enabled) {
    if (impl_->learning == enabled) return;
    impl_->learning = enabled;
    // Traces from before the switch belong to no TD error that will follow it.
    impl_->resetShortTermMemory();
}

bool Agent::learning() const { return impl_->learning; }
const AgentDescriptor& Agent::descriptor() const { return impl_->desc; }
AgentStats Agent::stats() const { return impl_->stats; }
float Agent::valueEstimate() const { return impl_->stats.value; }
float Agent::tdError() const { return impl_->stats.tdError; }
std::size_t Agent::rbfCount() const { return impl_->rep.featureCount(); }

}  // namespace verve
