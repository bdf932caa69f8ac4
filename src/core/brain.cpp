// verve::Brain: the shared part of an agent, and bodies made over it.
#include "verve/brain.hpp"

#include "core/agent_impl.hpp"

namespace verve {

Brain::Brain(const AgentDescriptor& descriptor) : state_(std::make_shared<BrainState>(descriptor)) {}
// The whole agent is restored (and validated), then only its brain is kept.
Brain::Brain(const AgentSnapshot& snapshot) : state_(restoreAgent(snapshot)->brain) {}
Brain::~Brain() = default;
Brain::Brain(Brain&&) noexcept = default;
Brain& Brain::operator=(Brain&&) noexcept = default;

Agent Brain::makeBody() {
    const std::uint64_t seed = core::streamSeed(state_->desc.seed, state_->bodiesMade);
    auto body = std::make_unique<Agent::Impl>(state_, seed);
    body->sharesBrain = true;
    ++state_->bodiesMade;
    return Agent(std::move(body));
}

const AgentDescriptor& Brain::descriptor() const { return state_->desc; }
std::size_t Brain::rbfCount() const { return state_->rep.featureCount(); }
std::uint64_t Brain::bodiesMade() const { return state_->bodiesMade; }

AgentSnapshot Brain::snapshot() const {
    AgentSnapshot snap;
    snapshotBrain(*state_, snap);
    snap.rng = core::Rng(state_->desc.seed).state();
    return snap;
}

}  // namespace verve
