// Agent shapes and observation streams shared by the benchmarks and verve_update_count.
#pragma once
#include <cmath>
#include <cstdint>

#include "verve/agent.hpp"

namespace verve::bench {

// Classic cart-pole equations (Barto, Sutton & Anderson 1983), Euler steps of 0.01 s: enough to give
// the agent the observation stream of a real balancing task without a physics engine in the loop.
struct CartPole {
    double x = 0, v = 0, theta = 0, omega = 0;
    void step(double force) {
        const double g = 9.81, cartMass = 1.0, poleMass = 0.1, halfLength = 0.5, total = cartMass + poleMass;
        const double c = std::cos(theta), s = std::sin(theta);
        const double tmp = (force + poleMass * halfLength * omega * omega * s) / total;
        const double alpha = (g * s - c * tmp) / (halfLength * (4.0 / 3.0 - poleMass * c * c / total));
        const double a = tmp - poleMass * halfLength * alpha * c / total;
        x += 0.01 * v;
        v += 0.01 * a;
        theta += 0.01 * omega;
        omega += 0.01 * alpha;
    }
    bool failed() const { return std::fabs(x) > 2.4 || std::fabs(theta) > 12.0 * M_PI / 180.0; }
    void observe(Observation& o) const {
        o.continuous = {float(x / 2.4), float(v / 2.4), float(theta / (12.0 * M_PI / 180.0)),
                        float(omega / (100.0 * M_PI / 180.0))};
    }
};

// One agent step of the cart-pole scene: 5 physics steps of 0.01 s, then Agent::update.
class CartPoleRun {
public:
    explicit CartPoleRun(Agent& agent) : agent_(agent) { restart(); }
    void step() {
        const double force = action_ == 0 ? -10.0 : action_ == 1 ? 10.0 : 0.0;
        for (int k = 0; k < 5; ++k) cart_.step(force);
        if (cart_.failed()) {
            agent_.endEpisode(-1.0f);
            restart();
            return;
        }
        cart_.observe(obs_);
        action_ = agent_.update(1.0f, obs_, 0.05f);
    }

private:
    void restart() {
        cart_ = CartPole{};
        cart_.theta = 0.01 * static_cast<double>((trial_++ % 7) - 3);
        cart_.observe(obs_);
        action_ = agent_.update(0.0f, obs_, 0.05f);
    }
    Agent& agent_;
    CartPole cart_;
    Observation obs_;
    std::uint32_t action_ = 0;
    int trial_ = 0;
};

inline AgentDescriptor cartPoleAgent() {
    AgentDescriptor d;
    for (int i = 0; i < 4; ++i) d.addContinuousSensor();
    d.resolution = 8;
    d.numActions = 3;
    d.tauValue = 0.001f;
    d.policyMultiplier = 50.0f;
    return d;
}

// A dense space: the full lattice of `dims` continuous sensors at `resolution`, 3 actions.
inline AgentDescriptor denseAgent(int dims, std::uint32_t resolution) {
    AgentDescriptor d;
    for (int i = 0; i < dims; ++i) d.addContinuousSensor();
    d.resolution = resolution;
    d.numActions = 3;
    d.allocation = RbfAllocation::Full;
    return d;
}

// Updates along a smooth path through the interior of [-1, 1]^n, with incommensurate frequencies
// per sensor so that over a benchmark run it visits the whole space rather than one corner.
class PathRun {
public:
    PathRun(Agent& agent, const AgentDescriptor& d) : agent_(agent), obs_(d) {}
    void step() {
        static constexpr float kFrequency[4] = {1.3f, 0.7f, 1.1f, 0.9f};
        ++step_;
        const float t = 0.013f * static_cast<float>(step_);
        for (std::size_t d = 0; d < obs_.continuous.size(); ++d) {
            obs_.continuous[d] = 0.9f * std::sin(t * kFrequency[d % 4] + float(d));
        }
        agent_.update(std::sin(0.065f * static_cast<float>(step_)), obs_, 0.1f);
    }

private:
    Agent& agent_;
    Observation obs_;
    std::uint64_t step_ = 0;
};

}  // namespace verve::bench
