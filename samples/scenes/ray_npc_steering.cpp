#include "ray_npc_steering.hpp"

#include <algorithm>
#include <cmath>

#include "scene_util.hpp"

namespace verve::scenes {

std::uint32_t scriptedSteering(const Observation& obs, const RayNpcConfig& config) {
    using Scene = RayNpcScene;
    const double kClear = 1.0;                 // m: a ray this open is a way to walk
    const double kTurnInPlace = radians(50);   // beyond this, walking would only circle
    const double kStraight = radians(10);
    const double kBrush = 0.2;                 // m: closer than this at the side is a scrape coming
    const std::uint32_t n = config.rays;
    const double bearing = obs.continuous.at(n) * kPi;
    const double diagonal = 2.0 * std::sqrt(2.0) * config.layout.halfSize;
    const double targetDistance = (obs.continuous.at(n + 1) + 1.0) / 2.0 * diagonal;
    const auto rayDistance = [&](std::uint32_t i) { return (obs.continuous.at(i) + 1.0) / 2.0 * config.rayRange; };
    const auto isFree = [&](std::uint32_t i) {
        return rayDistance(i) >= std::min(kClear, targetDistance - config.reachRadius);
    };

    // Where to go: straight at the target when the rays either side of it are free, else along
    // the free ray closest to it; the most open ray when none is free. A target outside the
    // rays' arc is turned to first.
    double desired = bearing;
    bool boxedIn = false;
    if (std::abs(bearing) <= config.rayArc / 2) {
        std::uint32_t best = n, open = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            if (rayDistance(i) > rayDistance(open)) open = i;
            if (!isFree(i)) continue;
            if (best == n || std::cos(Scene::rayAngle(config, i) - bearing) >
                                 std::cos(Scene::rayAngle(config, best) - bearing))
                best = i;
        }
        std::uint32_t below = 0;  // the rays either side of the bearing: below and below + 1
        while (below + 2 < n && Scene::rayAngle(config, below + 1) < bearing) ++below;
        if (isFree(below) && isFree(below + 1)) {
            desired = bearing;
        } else if (best < n) {
            desired = Scene::rayAngle(config, best);
        } else {
            desired = Scene::rayAngle(config, open);
            boxedIn = true;
        }
    }

    const std::int32_t hazard = obs.discrete.at(0);
    if (hazard == Scene::Inside) {
        // Keep walking: stopping to turn only keeps the NPC inside longer.
        if (std::abs(desired) < kStraight) return Scene::Forward;
        return desired > 0 ? Scene::ForwardLeft : Scene::ForwardRight;
    }
    if (hazard == Scene::Ahead) {
        // Turn off to the target's side (left when it lies straight beyond): at speed, in place,
        // which brakes (an arc at full speed is wider than the hazard); slowly, along an arc.
        const bool right = bearing < -kStraight;
        if (obs.continuous.at(n + 2) > 0.3f) return right ? Scene::TurnRight : Scene::TurnLeft;
        return right ? Scene::ForwardRight : Scene::ForwardLeft;
    }
    if (boxedIn || std::abs(desired) > kTurnInPlace) return desired > 0 ? Scene::TurnLeft : Scene::TurnRight;
    // Shy away from a wall or box brushing a side: context steering alone slides along it.
    double nearestLeft = config.rayRange, nearestRight = config.rayRange;
    for (std::uint32_t i = 0; i < n; ++i) {
        const double a = Scene::rayAngle(config, i);
        if (a > kStraight && a <= kPi / 2) nearestLeft = std::min(nearestLeft, rayDistance(i));
        if (a < -kStraight && a >= -kPi / 2) nearestRight = std::min(nearestRight, rayDistance(i));
    }
    if (nearestRight < kBrush && nearestRight < nearestLeft && desired <= kStraight) return Scene::ForwardLeft;
    if (nearestLeft < kBrush && nearestLeft < nearestRight && desired >= -kStraight) return Scene::ForwardRight;
    if (std::abs(desired) > kStraight) return desired > 0 ? Scene::ForwardLeft : Scene::ForwardRight;
    return Scene::Forward;
}

}  // namespace verve::scenes
