// Where things are in the raycast NPC scene's arena (samples/scenes/ray_npc.hpp), drawn from its
// seed: a hazard disc and a few axis-aligned box obstacles, plus the geometry the scene asks of them
// (is a spot free for an NPC or a target item). Plain 2D geometry on the floor plane (x, z): the
// Bullet world is built from it, and nothing here needs Bullet.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "scene_random.hpp"

namespace verve::scenes {

struct Vec2 {
    double x = 0, z = 0;
};

inline double distance(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.z - b.z); }

struct Box2 {
    Vec2 centre;
    double half = 0;  // half the side: obstacles are square in plan
};

struct RayNpcLayoutConfig {
    double halfSize = 5.0;       // m; walls at +-halfSize on x and z
    std::uint32_t obstacles = 5;
    double obstacleMinHalf = 0.3, obstacleMaxHalf = 0.6;  // m
    // m kept free between two obstacles and between an obstacle and a wall: wider than an NPC
    // (0.6 m), so clutter never walls off part of the arena.
    double passage = 0.9;
    double hazardRadius = 1.2;   // m
};

class RayNpcLayout {
public:
    // Draws the hazard, then the obstacles, from `random` (a bounded number of tries: a config
    // with no room throws verve::Error(InvalidArgument)).
    RayNpcLayout(const RayNpcLayoutConfig& config, SceneRandom& random);

    const std::vector<Box2>& obstacles() const { return obstacles_; }
    Vec2 hazardCentre() const { return hazard_; }
    double hazardRadius() const { return config_.hazardRadius; }
    double halfSize() const { return config_.halfSize; }

    bool inHazard(Vec2 p) const;
    // Distance from p to the nearest obstacle's or wall's surface (negative inside an obstacle).
    double clearance(Vec2 p) const;
    // A random spot at least `clear` m from every obstacle and wall, `hazardGap` m outside the
    // hazard's edge, and `apart` m from each of `others`. Throws when none is found in many tries.
    Vec2 freeSpot(SceneRandom& random, double clear, double hazardGap, const std::vector<Vec2>& others = {},
                  double apart = 0.0) const;

private:
    RayNpcLayoutConfig config_;
    Vec2 hazard_;
    std::vector<Box2> obstacles_;
};

}  // namespace verve::scenes
