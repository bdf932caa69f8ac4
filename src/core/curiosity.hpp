// Curiosity rewards for imagined steps (thesis chapter 2, "Planning with Curiosity").
// Novelty (thesis, after Singh, Barto & Chentanez): proportional to the model's predicted
// uncertainty, so the agent is drawn to what it cannot yet predict -- including pure noise.
// Progress (after Schmidhuber): proportional to how fast the prediction error has been falling
// (slow minus fast error average), so an unlearnable noise source, whose error never falls,
// stops being attractive once the two averages agree.
#pragma once
#include "core/predictive_model.hpp"
#include "verve/agent_descriptor.hpp"

namespace verve::core {

inline float curiosityReward(CuriosityMode mode, float factor, const Prediction& p) {
    switch (mode) {
        case CuriosityMode::Novelty: return factor * p.uncertainty;
        case CuriosityMode::Progress: return factor * p.progress;
        default: return 0.0f;
    }
}

}  // namespace verve::core
