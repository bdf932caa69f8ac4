// How far ahead the rewards that matter lie within a trial (docs/algorithm.md, "A horizon that
// follows the rewards"): the longest stretch of the trial over which the step reward did not change.
// With -1 a step until a goal (MountainCar-v0, Acrobot-v1, the hot plates, the corridor) nothing
// changes until the trial ends: the stretch is the whole trial, and the horizon follows the trials
// as before. With a reward that says something on every step (progress towards a target, a
// pendulum's height) the stretches are a step or two long: the next informative reward is never
// far, and a long horizon only blurs it. A car rewarded for its progress learned to drive to its
// targets in 80 steps with the user's 1 s horizon and in 182 with the trials' (the sum of its
// progress rewards is the same however slowly it drives: only the discount makes haste pay).
#pragma once
#include <algorithm>

namespace verve::core {

struct RewardStretch {
    float seconds = 0.0f;  // since the step reward last changed (or the trial began)
    float longest = 0.0f;  // the trial's longest finished stretch
    float last = 0.0f;     // the latest step reward learned
    bool seen = false;     // whether the trial has learned a step reward yet

    // A learning update of dt seconds; `learned`: it learned step reward r (it had a previous step).
    void see(bool learned, float r, float dt) {
        if (learned) {
            if (!seen) {
                last = r;
                seen = true;
            } else if (r != last) {
                longest = std::max(longest, seconds);
                seconds = 0.0f;
                last = r;
            }
        }
        seconds += dt;
    }
    float trialLongest() const { return std::max(longest, seconds); }
    void reset() { *this = RewardStretch{}; }
};

}  // namespace verve::core
