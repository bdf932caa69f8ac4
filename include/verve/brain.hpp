// One brain, many bodies: a shared learner (RBFs, weights, model) that many NPCs of one kind step
// through. Each body is an Agent with its own short-term memory (eligibility traces, previous step,
// random stream) and all of them train the same weights, so what one NPC learns, all know.
//
// Thread rules: a brain and all its bodies count as one agent: one thread at a time (a Batch
// updates the bodies of one brain in parallel, in phases whose result depends only on their
// order: docs/crowds.md). A body keeps its brain alive: destroying the Brain first is fine.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>

#include "verve/agent.hpp"

namespace verve {

struct BrainState;  // internal (src/core/brain_state.hpp)

class Brain {
public:
    explicit Brain(const AgentDescriptor& descriptor);  // throws Error(InvalidArgument)
    // From a save (an agent's or a brain's): its RBFs and weights; short-term memory is not kept.
    explicit Brain(const AgentSnapshot& snapshot);      // throws Error(Format) if inconsistent
    ~Brain();
    Brain(Brain&&) noexcept;
    Brain& operator=(Brain&&) noexcept;
    Brain(const Brain&) = delete;
    Brain& operator=(const Brain&) = delete;

    // A new body. Body k (counting from 0 over this brain's life) draws its actions from a random
    // stream derived from the descriptor's seed and k: the same bodies, the same runs.
    Agent makeBody();

    const AgentDescriptor& descriptor() const;
    std::size_t rbfCount() const;
    std::uint64_t bodiesMade() const;
    // The brain as an agent save without short-term memory: loads as a Brain or as an Agent.
    AgentSnapshot snapshot() const;

private:
    std::shared_ptr<BrainState> state_;
};

}  // namespace verve
