// What the bodies of one brain share: the descriptor, the RBFs and the learned weights. A plain
// Agent owns one of its own; a verve::Brain hands the same one to every body it makes.
#pragma once
#include <cstdint>

#include "core/group_rates.hpp"
#include "core/horizon.hpp"
#include "core/state_representation.hpp"
#include "core/td_scale.hpp"
#include "core/td_learner.hpp"
#include "core/weight_table.hpp"
#include "verve/agent_descriptor.hpp"

namespace verve {

struct BrainState {
    explicit BrainState(const AgentDescriptor& d);

    // What every update reads comes first, the representation (whose tail is cold) last, so that
    // an update of a crowd's agent touches as few of this struct's cache lines as it can. A batch
    // reads every agent's brain once before it updates any (the descriptor's sensor lists, for its
    // check); it writes nothing here: its grouping by brain is its own (batch.cpp), so two batches
    // that meet one brain cannot corrupt each other's.
    AgentDescriptor desc;
    core::WeightTable weights;
    // The real rewards every body has learned from: they bound the values TD errors bootstrap from.
    core::RewardRange rewards;
    // Whether the model's continuous outputs are changes (core/predictive_model.hpp): true for every
    // brain made now, false for one loaded from a save that predates them, which keeps its meaning.
    bool modelPredictsChange = true;
    // What the adaptations measure over every body's experience (AgentDescriptor::adaptation):
    // how long trials last (core/horizon.hpp), how large TD errors are (core/td_scale.hpp) and, at
    // the end, which sensor groups predict them (core/group_rates.hpp).
    core::AdaptiveHorizon horizon;
    core::TdScale tdScale;
    std::uint64_t bodiesMade = 0;  // numbers each new body's random stream
    core::StateRepresentation rep;
    // How fast each sensor group learns (Adaptation::GroupRates; after rep, which it reads).
    core::GroupRates groupRates;
};

}  // namespace verve
