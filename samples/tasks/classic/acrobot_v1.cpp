#include "tasks/classic/acrobot_v1.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace verve::tasks {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDt = 0.2, kMaxVel1 = 4 * kPi, kMaxVel2 = 9 * kPi;
using Vec = std::array<double, 4>;

// d/dt of (theta1, theta2, dtheta1, dtheta2) under `torque`: unit masses, lengths and moments of
// inertia, centres of mass at half length, g = 9.8 (Sutton and Barto's equations).
Vec derivatives(const Vec& s, double torque) {
    constexpr double m1 = 1, m2 = 1, l1 = 1, lc1 = 0.5, lc2 = 0.5, i1 = 1, i2 = 1, g = 9.8;
    const double t1 = s[0], t2 = s[1], dt1 = s[2], dt2 = s[3];
    const double d1 = m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * std::cos(t2)) + i1 + i2;
    const double d2 = m2 * (lc2 * lc2 + l1 * lc2 * std::cos(t2)) + i2;
    const double phi2 = m2 * lc2 * g * std::cos(t1 + t2 - kPi / 2);
    const double phi1 = -m2 * l1 * lc2 * dt2 * dt2 * std::sin(t2) - 2 * m2 * l1 * lc2 * dt2 * dt1 * std::sin(t2) +
                        (m1 * lc1 + m2 * l1) * g * std::cos(t1 - kPi / 2) + phi2;
    const double ddt2 = (torque + d2 / d1 * phi1 - m2 * l1 * lc2 * dt1 * dt1 * std::sin(t2) - phi2) /
                        (m2 * lc2 * lc2 + i2 - d2 * d2 / d1);
    const double ddt1 = -(d2 * ddt2 + phi1) / d1;
    return {dt1, dt2, ddt1, ddt2};
}

Vec plus(const Vec& a, const Vec& b, double k) { return {a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2], a[3] + k * b[3]}; }

// Gymnasium's wrap: by whole turns into [-pi, pi] (pi itself stays).
double wrap(double x) {
    while (x > kPi) x -= 2 * kPi;
    while (x < -kPi) x += 2 * kPi;
    return x;
}

}  // namespace

AcrobotV1::AcrobotV1() : ClassicTask(500, static_cast<float>(kDt)) {
    descriptor_.addContinuousSensor(true);
    descriptor_.addContinuousSensor(true);
    descriptor_.addContinuousSensor();
    descriptor_.addContinuousSensor();
    descriptor_.numActions = 3;
}

void AcrobotV1::beginTrial(std::uint64_t seed) {
    rng_ = TaskRng(seed);
    // Gymnasium draws the start in float32.
    for (double* v : {&state_.theta1, &state_.theta2, &state_.dtheta1, &state_.dtheta2}) {
        *v = static_cast<float>(-0.1 + 0.2 * rng_.uniform());
    }
}

void AcrobotV1::observe(Observation& out) const {
    out.setContinuous(0, static_cast<float>(state_.theta1 / kPi));
    out.setContinuous(1, static_cast<float>(state_.theta2 / kPi));
    out.setContinuous(2, static_cast<float>(state_.dtheta1 / kMaxVel1));
    out.setContinuous(3, static_cast<float>(state_.dtheta2 / kMaxVel2));
}

bool AcrobotV1::step(AcrobotState& st, std::uint32_t action) {
    const double torque = static_cast<double>(action) - 1.0;
    const Vec s{st.theta1, st.theta2, st.dtheta1, st.dtheta2};
    const Vec k1 = derivatives(s, torque);
    const Vec k2 = derivatives(plus(s, k1, kDt / 2), torque);
    const Vec k3 = derivatives(plus(s, k2, kDt / 2), torque);
    const Vec k4 = derivatives(plus(s, k3, kDt), torque);
    Vec n;
    for (int i = 0; i < 4; ++i) n[i] = s[i] + kDt / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    st.theta1 = wrap(n[0]);
    st.theta2 = wrap(n[1]);
    st.dtheta1 = std::clamp(n[2], -kMaxVel1, kMaxVel1);
    st.dtheta2 = std::clamp(n[3], -kMaxVel2, kMaxVel2);
    return -std::cos(st.theta1) - std::cos(st.theta2 + st.theta1) > 1.0;
}

StepResult AcrobotV1::act(std::uint32_t action) {
    if (action >= 3) throw std::invalid_argument("AcrobotV1::act: no such action");
    const bool terminal = step(state_, action);
    gymnasiumReward_ = terminal ? 0.0 : -1.0;
    return StepResult{static_cast<float>(gymnasiumReward_), terminal};
}

}  // namespace verve::tasks
