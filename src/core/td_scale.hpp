// The actor's step, kept to the scale of rewards (docs/algorithm.md, "Learning at defaults").
// TD errors grow with the horizon: with -1 per step and a horizon of hundreds of steps, values and
// their errors run into the tens, and an actor stepping by them saturates on whatever it did first
// (the continuous maze #2, seeds 1-4: 2457-5292 steps a trial with the long horizon alone, 40-1386
// with this). The actor's rate is divided by the running root mean square of the TD errors
// whenever that is above 1, the largest a reward is; below it nothing changes, so tasks with short
// horizons learn as before.
#pragma once
#include <algorithm>
#include <cmath>

namespace verve::core {

struct TdScale {
    // A running mean over about 1000 real updates.
    static constexpr float kAveraging = 0.001f;

    float meanSquare = 0.0f;

    void see(float delta) { meanSquare += kAveraging * (delta * delta - meanSquare); }
    // The factor for the actor's rate: 1 while errors are reward-sized, smaller beyond.
    float actorFactor() const { return 1.0f / std::max(1.0f, std::sqrt(meanSquare)); }
};

}  // namespace verve::core
