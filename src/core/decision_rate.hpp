// Learning per decision (docs/algorithm.md, "Learning at defaults"). The time constants say how
// fast the critic and the actor learn and how long eligibility lasts, in seconds, and the thesis
// turns them into per-update constants with dt. Its tasks decide every 0.1 s. A host that calls
// 50-60 times a second makes each update a fifth or a sixth of such a decision, and the agent then
// learned far too little from each: consecutive states are almost the same, and CartPole-v1 (dt
// 0.02) was never solved at the defaults (last-100 means 343-385 at 300k steps) while
// MountainCar-v0 (dt 1/30) took a median of 146k steps. So the learning rates and the trace decay of
// an update come from max(dt, kSeconds): every update learns at least as much as one 0.1 s
// decision, and eligibility spans about as many decisions as at 10 decisions a second. Discounting
// and the horizon stay in real seconds (as if dt were 0.1 there too, CartPole lost 3 of 6 seeds).
// Updates 0.1 s or more apart (every thesis task, Acrobot-v1's 0.2 s) are exactly as before.
#pragma once
#include <algorithm>

namespace verve::core {

struct DecisionRate {
    // Measured on CartPole-v1 and MountainCar-v0 (seeds 1-10): 0.05 s solved MountainCar on 4 of 6
    // seeds (median 314k steps), 0.2 s on 6 of 10; 0.1 s on 9 of 10 (median 67k).
    static constexpr float kSeconds = 0.1f;
    // The seconds an update of dt counts for in the learning rates and the trace decay.
    static float learningSeconds(float dt) { return std::max(dt, kSeconds); }
};

}  // namespace verve::core
