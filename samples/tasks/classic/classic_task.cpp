#include "tasks/classic/classic_task.hpp"

#include <cmath>

namespace verve::tasks {

double wrapAngle(double radians) {
    constexpr double kPi = 3.14159265358979323846;
    const double r = std::fmod(radians + kPi, 2 * kPi);
    return (r < 0 ? r + 2 * kPi : r) - kPi;
}

}  // namespace verve::tasks
