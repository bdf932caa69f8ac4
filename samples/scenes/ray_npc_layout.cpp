#include "ray_npc_layout.hpp"

#include <algorithm>
#include <cmath>

#include "verve/error.hpp"

namespace verve::scenes {

namespace {
constexpr int kTries = 10000;  // draws before a spot counts as impossible

// Distance from p to a square's surface; negative inside.
double boxDistance(Vec2 p, const Box2& b) {
    const double dx = std::abs(p.x - b.centre.x) - b.half;
    const double dz = std::abs(p.z - b.centre.z) - b.half;
    if (dx <= 0 && dz <= 0) return std::max(dx, dz);
    return std::hypot(std::max(dx, 0.0), std::max(dz, 0.0));
}
}  // namespace

RayNpcLayout::RayNpcLayout(const RayNpcLayoutConfig& config, SceneRandom& random) : config_(config) {
    const double h = config.halfSize;
    if (h < 3.0 || config.hazardRadius <= 0 || config.obstacleMinHalf <= 0 ||
        config.obstacleMaxHalf < config.obstacleMinHalf)
        throw Error(ErrorCode::InvalidArgument, "ray npc: the arena needs a half size of 3 m or more and positive sizes");
    // The hazard lies wholly inside, a passage away from the walls, so NPCs can walk round it.
    const double reach = h - config.hazardRadius - config.passage;
    if (reach <= 0) throw Error(ErrorCode::InvalidArgument, "ray npc: the hazard does not fit in the arena");
    hazard_ = {random.uniform(-reach, reach), random.uniform(-reach, reach)};

    for (std::uint32_t i = 0; i < config.obstacles; ++i) {
        for (int t = 0;; ++t) {
            if (t == kTries) throw Error(ErrorCode::InvalidArgument, "ray npc: no room for the obstacles");
            Box2 b;
            b.half = random.uniform(config.obstacleMinHalf, config.obstacleMaxHalf);
            const double edge = h - config.passage - b.half;
            b.centre = {random.uniform(-edge, edge), random.uniform(-edge, edge)};
            // A passage from the hazard too: the way round it is never blocked.
            if (boxDistance(hazard_, b) < config.hazardRadius + config.passage) continue;
            const bool crowded = std::any_of(obstacles_.begin(), obstacles_.end(), [&](const Box2& o) {
                // Square boxes: apart when the gap along x or along z is a passage wide.
                const double gap = std::max(std::abs(o.centre.x - b.centre.x), std::abs(o.centre.z - b.centre.z)) -
                                   o.half - b.half;
                return gap < config.passage;
            });
            if (crowded) continue;
            obstacles_.push_back(b);
            break;
        }
    }
}

bool RayNpcLayout::inHazard(Vec2 p) const {
    return distance(p, hazard_) < config_.hazardRadius;
}

double RayNpcLayout::clearance(Vec2 p) const {
    const double h = config_.halfSize;
    double d = std::min({h - p.x, h + p.x, h - p.z, h + p.z});
    for (const Box2& b : obstacles_) d = std::min(d, boxDistance(p, b));
    return d;
}

Vec2 RayNpcLayout::freeSpot(SceneRandom& random, double clear, double hazardGap, const std::vector<Vec2>& others,
                            double apart) const {
    const double edge = config_.halfSize - clear;
    for (int t = 0; t < kTries; ++t) {
        const Vec2 p{random.uniform(-edge, edge), random.uniform(-edge, edge)};
        if (clearance(p) < clear) continue;
        if (distance(p, hazard_) < config_.hazardRadius + hazardGap) continue;
        if (std::any_of(others.begin(), others.end(),
                        [&](Vec2 o) { return distance(o, p) < apart; }))
            continue;
        return p;
    }
    throw Error(ErrorCode::InvalidArgument, "ray npc: no free spot left in the arena");
}

}  // namespace verve::scenes
