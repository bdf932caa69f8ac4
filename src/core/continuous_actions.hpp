// Continuous actions (docs/algorithm.md, "Continuous actions"): a steering angle, a throttle or a
// torque, each a bounded value in [-1, 1] chosen on every step beside the discrete action. Each
// dimension d is a Gaussian in preference space squashed by tanh: u = x_d + sigma_d * n, action
// tanh(u), where the mean preference x_d and the spread preference y_d (sigma_d = kSpreadLow +
// (kSpreadHigh - kSpreadLow) * sigmoid(y_d)) are linear in the features, two more actor columns per
// dimension after the discrete ones. The one TD error credits them through eligibility traces of
// the policy's natural gradient (Sutton & Barto 13.7; natural, so that a narrow spread does not
// blow the steps up): the mean's trace gathers (u - x) * phi, the spread's (n^2 - 1) / 2 * phi,
// so a deviation that turned out better than expected pulls the mean towards it, and the spread
// widens where deviations pay and narrows where they do not. Greedy play takes the mean.
//
// The noise n is correlated over kNoiseSeconds, not drawn afresh on every update: a host calling
// 50 times a second would otherwise average its own exploration away within a tenth of a second,
// and a pendulum could never be pushed long enough to swing (time-scale aware, as every rate here).
#pragma once
#include <cstdint>
#include <vector>

#include "core/rng.hpp"

namespace verve::core {

struct ContinuousPolicy {
    // sigma's floor and ceiling, in preference units (tanh'(0) = 1); a new state's is their middle,
    // 0.95. Learned freely, the spread shrank where deviations cost more than they found, and a
    // narrow spread then taught the mean nothing (its step is u - x): the car below stopped driving
    // (its throttle's spread and mean went to 0; 154 -> 382 steps per trial over 1,500 trials). With
    // the floor at 0.4 the car keeps 219-244 steps (seeds 1-3, trials 1401-1500; a fixed 0.775:
    // 156-230, floor 0.2: 233-248) and Pendulum-v1 solves 11 of 16 seeds as with 0.05.
    static constexpr float kSpreadLow = 0.4f;
    static constexpr float kSpreadHigh = 1.5f;
    static constexpr float kNoiseSeconds = 0.1f; // the noise's correlation time: one decision
    // The mean's and the spread's weights stay within +-kWeightBound: a preference beyond about +-3
    // no longer moves tanh, and a habit there could not be unlearned (core/habit_bound.hpp's lesson).
    static constexpr float kWeightBound = 4.0f;
    // A continuous preference moves the action itself where a discrete neuron's moves a probability
    // in a roulette: at the discrete actor's step the policy found a swing-up and lost it again.
    // Measured on Pendulum-v1 with continuous torque (resolution 16, policy multiplier 5, mean
    // return of the last 100 episodes after 100k steps): 1 solved 0 of 4 seeds (-992), 0.2 2 of 8
    // (-468), 0.1 12 of 16 (-234), 0.05 5 of 8 (-259).
    static constexpr float kStepScale = 0.1f;
    // The running noise stays within it (one draw's radius is at most sqrt(2 ln 2^24) = 5.8; a run
    // of large draws is clamped): a save's noise beyond it is corrupt.
    static constexpr float kNoiseLimit = 6.0f;
    static float spread(float y);
};

class ContinuousActions {
public:
    explicit ContinuousActions(std::uint32_t count);

    std::uint32_t count() const { return count_; }
    std::uint32_t columns() const { return 2 * count_; }  // actor columns: x_d and y_d of each dimension

    // The step's values from the state's column sums `sums` (x_0, y_0, x_1, y_1, ...): sampled with
    // the correlated noise, or the mean when `greedy` (no draw). `dt` seconds since the last update.
    // Leaves in gradients() what mark() adds to each column's trace (0s when greedy).
    void act(const float* sums, Rng& rng, float dt, bool greedy);
    // A teacher's values instead (core/continuous_demonstration.hpp): no draw, the noise kept; the
    // gradients those values would have left.
    void play(const float* sums, const float* demonstrated);
    const std::vector<float>& values() const { return values_; }
    const float* gradients() const { return gradients_.data(); }

    // The noise restarts (a trial's start): its next value is drawn afresh.
    void resetNoise();
    // Short-term memory, saved with the agent: the noise per dimension and whether it is running.
    const std::vector<float>& noise() const { return noise_; }
    bool noiseRunning() const { return running_; }
    void restore(const std::vector<float>& noise, bool running, const std::vector<float>& values);

private:
    std::uint32_t count_;
    bool running_ = false;
    std::vector<float> values_;     // the latest values in [-1, 1]
    std::vector<float> noise_;      // n per dimension, unit variance
    std::vector<float> gradients_;  // per column, as sums
};

// A standard normal draw (Box-Muller on two of the generator's uniforms).
float normalDraw(Rng& rng);

}  // namespace verve::core
