// Habits a changed world can undo (docs/algorithm.md, "Habits a changed world can undo").
// An actor weight is the input of its action's sigmoid: above +10 it adds less than 5e-5 to the
// action's chance, but every unit above is one more unit failures must take away before another
// action is tried. A mastered cue's action reached +75..+90 and, once the rules changed, never
// fell below its alternatives (cue-change at defaults: 72% correct after the change). With
// Adaptation::HabitBound and no policy_weight_bound, actor weights stay at or below kCeiling.
// Below, nothing: an action that keeps failing may fall as far as its failures take it. Bounded
// at -10 too, every MountainCar-v0 action piled at the floor while -1 per step pushed all of them
// down, and no seed was solved (0/10; 10/10 with the ceiling alone).
#pragma once
#include <algorithm>
#include <limits>

namespace verve::core {

// The range the actor's weights are kept within after every step that moves them.
struct PolicyRange {
    float low = -std::numeric_limits<float>::infinity();
    float high = std::numeric_limits<float>::infinity();

    // The user's policy_weight_bound B: [-B, B] (0: unbounded).
    static PolicyRange symmetric(float bound) {
        return bound > 0.0f ? PolicyRange{-bound, bound} : PolicyRange{};
    }
    // Whether a step moving weights the way `direction` points (its sign) can leave the range.
    bool crossable(float direction) const {
        return direction > 0.0f ? high < std::numeric_limits<float>::infinity()
                                : direction < 0.0f && low > -std::numeric_limits<float>::infinity();
    }
    float clamp(float w) const { return std::clamp(w, low, high); }
};

struct HabitBound {
    // sigma(10) = 0.99995. Measured on the defaults table (docs/experiments.md): 6 and 20 were
    // worse overall (6: the curious grid 30.2 -> 9.6 reward; 20: the cue task 0.94 -> 0.82).
    static constexpr float kCeiling = 10.0f;
    static PolicyRange range() { return PolicyRange{-std::numeric_limits<float>::infinity(), kCeiling}; }
};

}  // namespace verve::core
