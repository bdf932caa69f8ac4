// The discount horizon, set from the stream itself (docs/algorithm.md, "Learning at defaults").
// A user cannot be expected to know how far ahead an NPC must look: with -1 per step until a goal,
// a horizon much shorter than the way there reads every state at the same floor, and nothing can
// be learned (Acrobot-v1 and MountainCar-v0 never learned at the 1 s default). How long trials
// last measures that distance for the agent: the horizon is kTrialsPerHorizon times the recent
// mean trial length (of each trial's longest stretch of an unchanged step reward, which is the
// whole trial with -1 a step: core/reward_stretch.hpp), never shorter than tau_discount and never
// longer than kMaxSteps decisions
// (further than that, values are sums of thousands of rewards whose differences the critic cannot
// resolve: the 40-cell corridor took 431 steps at 1000, 39 at 300). A task whose trials never end
// keeps tau_discount.
#pragma once
#include <algorithm>
#include <cstdint>

namespace verve::core {

struct AdaptiveHorizon {
    static constexpr float kTrialsPerHorizon = 2.0f;
    static constexpr float kMaxSteps = 300.0f;
    // A running mean over about the last 20 trials (a plain mean over the first 20).
    static constexpr std::uint32_t kTrialWindow = 20;

    float meanTrialSeconds = 0.0f;
    std::uint32_t trials = 0;  // counted up to kTrialWindow

    void seeTrial(float seconds) {
        if (!(seconds > 0.0f)) return;
        trials = std::min(trials + 1, kTrialWindow);
        meanTrialSeconds += (seconds - meanTrialSeconds) / static_cast<float>(trials);
    }
    // The horizon in seconds for a user's tau_discount (its shortest) at decisions dt apart.
    float tauDiscount(float userTau, float dt) const {
        return std::max(userTau, std::min(kTrialsPerHorizon * meanTrialSeconds, kMaxSteps * dt));
    }
};

}  // namespace verve::core
