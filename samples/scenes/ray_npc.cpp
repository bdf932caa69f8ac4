#include "ray_npc.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "physics_world.hpp"
#include "ray_npc_steering.hpp"
#include "scene_util.hpp"
#include "verve/brain.hpp"

namespace verve::scenes {

namespace {
constexpr btScalar kRadius = 0.3f;        // capsule
constexpr btScalar kHeight = 0.6f;        // capsule's cylinder part
constexpr btScalar kMass = 1.0f;
constexpr btScalar kDrag = 0.99f;         // Bullet damping: velocity keeps (1 - d)^t per second
constexpr btScalar kWallThickness = 0.5f;
constexpr btScalar kObstacleHeight = 1.0f;
constexpr double kTouching = 0.01;        // m: a contact point this close counts as touching

// Who a collision object is (its Bullet user index): an NPC's index, or one of these.
constexpr int kFloor = -2;
constexpr int kSolid = -3;  // a wall or an obstacle

double dragRate() { return -std::log(1.0 - static_cast<double>(kDrag)); }

void addBox(PhysicsWorld& world, const btVector3& halfExtents, const btVector3& centre) {
    btTransform t;
    t.setIdentity();
    t.setOrigin(centre);
    world.addBody(std::make_unique<btBoxShape>(halfExtents), 0, t)->setUserIndex(kSolid);
}

// The closest hit along a ray, not counting the NPC that casts it.
struct RayFromNpc : btCollisionWorld::ClosestRayResultCallback {
    RayFromNpc(const btVector3& from, const btVector3& to, const btCollisionObject* self)
        : ClosestRayResultCallback(from, to), self_(self) {}
    bool needsCollision(btBroadphaseProxy* proxy) const override {
        return proxy->m_clientObject != self_ && ClosestRayResultCallback::needsCollision(proxy);
    }
    const btCollisionObject* self_;
};

btVector3 floorPoint(Vec2 p, btScalar y) { return {static_cast<btScalar>(p.x), y, static_cast<btScalar>(p.z)}; }
}  // namespace

RayNpcScene::RayNpcScene(const RayNpcConfig& config, std::uint64_t seed)
    : RayNpcScene(config, seed, defaultDescriptor(config)) {}

RayNpcScene::RayNpcScene(const RayNpcConfig& config, std::uint64_t seed, const AgentDescriptor& agents)
    : config_(config), random_(seed) {
    if (config.npcs == 0 || config.rays < 8 || config.rays > 16 || config.rayRange <= 0 || config.rayArc <= 0 ||
        config.rayArc > 2 * kPi || !(config.progressReward >= 0 && std::isfinite(config.progressReward)))
        throw Error(ErrorCode::InvalidArgument,
                    "ray npc: needs at least one NPC, 8 to 16 rays, a positive range, an arc up to 360 degrees and "
                    "a finite progress reward of 0 or more");
    agents.validate();
    if (agents.discreteSensors != std::vector<std::uint32_t>{3} ||
        agents.continuousSensors.size() != continuousSensors(config) || agents.numActions != kActions)
        throw Error(ErrorCode::InvalidArgument, "ray npc: agents need sensors {hazard(3)} + " +
                                                    std::to_string(continuousSensors(config)) + " continuous and " +
                                                    std::to_string(kActions) + " actions");
    layout_ = std::make_unique<RayNpcLayout>(config.layout, random_);
    buildWorld();

    std::unique_ptr<Brain> brain;  // with sharedBrain; its bodies keep it alive
    std::vector<Vec2> starts;
    for (std::uint32_t i = 0; i < config.npcs; ++i) {
        starts.push_back(layout_->freeSpot(random_, kRadius + 0.3, 0.5, starts, 1.5));
        btTransform t;
        t.setIdentity();
        t.setOrigin(floorPoint(starts.back(), kRadius + kHeight / 2));
        t.setRotation(btQuaternion(btVector3(0, 1, 0), static_cast<btScalar>(random_.uniform(-kPi, kPi))));
        btRigidBody* body = world_->addBody(std::make_unique<btCapsuleShape>(kRadius, kHeight), kMass, t);
        body->setAngularFactor(btVector3(0, 1, 0));  // stays upright, only turns
        body->setDamping(kDrag, kDrag);
        body->setUserIndex(static_cast<int>(i));
        bodies_.push_back(body);

        AgentDescriptor d = agents;
        d.seed = static_cast<std::uint64_t>(random_.uniform(0, 0x1.0p53));
        addNpcAgent(agents_, brain, d, config.sharedBrain);
    }
    for (std::uint32_t i = 0; i < config.npcs; ++i) {
        targets_.push_back(newTarget(i));
        targetDistance_.push_back(distance(position(i), targets_.back()));
    }
    rewards_.assign(config.npcs, 0.0f);
    actions_.assign(config.npcs, Forward);
    touching_.assign(config.npcs, false);
    touchedThisStep_.assign(config.npcs, false);
    totals_.npcs = config.npcs;
    scratch_ = Observation(agents);
}

RayNpcScene::~RayNpcScene() = default;

AgentDescriptor RayNpcScene::defaultDescriptor(const RayNpcConfig& config) {
    AgentDescriptor d;
    d.addDiscreteSensor(3);  // hazard: clear, ahead, inside
    for (std::uint32_t i = 0; i < config.rays; ++i) d.addContinuousSensor(false);
    d.addContinuousSensor(true);   // bearing to the target, circular
    d.addContinuousSensor(false);  // distance to it
    d.addContinuousSensor(false);  // forward speed
    d.addContinuousSensor(false);  // turn rate
    d.numActions = kActions;
    return d;
}

double RayNpcScene::rayAngle(const RayNpcConfig& config, std::uint32_t i) {
    const double arc = config.rayArc;
    if (arc >= 2 * kPi - 1e-6) return -kPi + i * arc / config.rays;
    return -arc / 2 + i * arc / (config.rays - 1);
}

void RayNpcScene::buildWorld() {
    world_ = std::make_unique<PhysicsWorld>();
    btTransform floor;
    floor.setIdentity();
    world_->addBody(std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), 0), 0, floor)->setUserIndex(kFloor);
    const btScalar h = static_cast<btScalar>(layout_->halfSize());
    addBox(*world_, btVector3(kWallThickness, 1, h), btVector3(h + kWallThickness, 1, 0));
    addBox(*world_, btVector3(kWallThickness, 1, h), btVector3(-h - kWallThickness, 1, 0));
    addBox(*world_, btVector3(h, 1, kWallThickness), btVector3(0, 1, h + kWallThickness));
    addBox(*world_, btVector3(h, 1, kWallThickness), btVector3(0, 1, -h - kWallThickness));
    for (const Box2& b : layout_->obstacles()) {
        const btScalar half = static_cast<btScalar>(b.half);
        addBox(*world_, btVector3(half, kObstacleHeight / 2, half), floorPoint(b.centre, kObstacleHeight / 2));
    }
}

Vec2 RayNpcScene::position(std::size_t npc) const {
    const btVector3 p = bodies_.at(npc)->getCenterOfMassPosition();
    return {p.x(), p.z()};
}

Vec2 RayNpcScene::heading(std::size_t npc) const {
    const btVector3 f = bodies_.at(npc)->getWorldTransform().getBasis().getColumn(0);  // local +x
    const double len = std::hypot(static_cast<double>(f.x()), static_cast<double>(f.z()));
    return {f.x() / len, f.z() / len};
}

Vec2 RayNpcScene::newTarget(std::size_t npc) {
    // Reachable (0.5 m from any wall or obstacle: an NPC's centre gets within 0.3 m), out of the
    // hazard with a margin, and a walk away from the NPC.
    return layout_->freeSpot(random_, 0.5, 0.3, {position(npc)}, 2.0);
}

double RayNpcScene::castRay(std::size_t npc, double angle) const {
    const Vec2 p = position(npc);
    const Vec2 f = heading(npc);
    // Turning the heading toward +z is a turn to the left (as the bearing counts it).
    const Vec2 d{f.x * std::cos(angle) - f.z * std::sin(angle), f.z * std::cos(angle) + f.x * std::sin(angle)};
    const double length = kRadius + config_.rayRange;
    const btScalar y = kRadius + kHeight / 2;
    const btVector3 from = floorPoint(p, y);
    const btVector3 to = floorPoint({p.x + d.x * length, p.z + d.z * length}, y);
    RayFromNpc hit(from, to, bodies_[npc]);
    world_->world().rayTest(from, to, hit);
    if (!hit.hasHit()) return config_.rayRange;
    return std::clamp(hit.m_closestHitFraction * length - kRadius, 0.0, static_cast<double>(config_.rayRange));
}

void RayNpcScene::observe(std::size_t npc, Observation& out) const {
    const Vec2 p = position(npc);
    const Vec2 f = heading(npc);
    const Vec2 to{targets_.at(npc).x - p.x, targets_.at(npc).z - p.z};
    const Vec2 ahead{p.x + f.x * config_.aheadDistance, p.z + f.z * config_.aheadDistance};
    const std::int32_t hazard = layout_->inHazard(p) ? Inside : layout_->inHazard(ahead) ? Ahead : Clear;
    out.discrete.assign({hazard});

    out.continuous.clear();
    for (std::uint32_t i = 0; i < config_.rays; ++i)
        out.continuous.push_back(static_cast<float>(2.0 * castRay(npc, rayAngle(config_, i)) / config_.rayRange - 1.0));

    const double bearing = std::atan2(f.x * to.z - f.z * to.x, f.x * to.x + f.z * to.z);
    const double diagonal = 2.0 * std::sqrt(2.0) * layout_->halfSize();
    const btRigidBody& body = *bodies_[npc];
    const btVector3 v = body.getLinearVelocity();
    const double forward = v.x() * f.x + v.z() * f.z;
    out.continuous.push_back(toSensor(bearing, kPi));
    out.continuous.push_back(static_cast<float>(2.0 * std::hypot(to.x, to.z) / diagonal - 1.0));
    out.continuous.push_back(toSensor(forward, config_.speed));
    // A left turn is a negative turn about y (see simulate()).
    out.continuous.push_back(toSensor(-body.getAngularVelocity().y(), config_.turnRate));
    for (float& c : out.continuous) c = std::clamp(c, -1.0f, 1.0f);
}

void RayNpcScene::act() {
    for (std::size_t i = 0; i < agents_.size(); ++i) {
        observe(i, scratch_);
        if (driver_ == Driver::Agents) {
            actions_[i] = agents_[i].update(rewards_[i], scratch_, config_.agentStep);
            continue;
        }
        actions_[i] = scriptedSteering(scratch_, config_);
        if (driver_ == Driver::ScriptDemonstrates)
            agents_[i].updateDemonstrated(rewards_[i], scratch_.view(), config_.agentStep, actions_[i]);
    }
}

void RayNpcScene::simulate() {
    // Full thrust or torque balances the drag at the configured speed or turn rate.
    const btScalar thrust = static_cast<btScalar>(kMass * dragRate() * config_.speed);
    std::fill(touchedThisStep_.begin(), touchedThisStep_.end(), false);
    const int subSteps = static_cast<int>(stepsIn(config_.agentStep, config_.physicsStep));
    for (int s = 0; s < subSteps; ++s) {
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            btRigidBody& body = *bodies_[i];
            const Vec2 f = heading(i);
            const btScalar inertia = 1 / body.getInvInertiaDiagLocal().y();
            const btScalar torque = static_cast<btScalar>(inertia * dragRate() * config_.turnRate);
            const std::uint32_t a = actions_[i];
            if (a == Forward || a == ForwardLeft || a == ForwardRight)
                body.applyCentralForce(btVector3(static_cast<btScalar>(f.x) * thrust, 0, static_cast<btScalar>(f.z) * thrust));
            // Local +x turning toward +z is a negative turn about y: "left" matches a positive bearing.
            if (a == TurnLeft || a == ForwardLeft) body.applyTorque(btVector3(0, -torque, 0));
            if (a == TurnRight || a == ForwardRight) body.applyTorque(btVector3(0, torque, 0));
        }
        world_->step(config_.physicsStep);

        // Contacts after every sub-step, so a glancing touch between agent steps still counts.
        std::vector<bool> now(bodies_.size(), false);
        btDispatcher& dispatcher = *world_->world().getDispatcher();
        for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
            const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
            const int a = manifold.getBody0()->getUserIndex(), b = manifold.getBody1()->getUserIndex();
            const int npc = a >= 0 && b == kSolid ? a : b >= 0 && a == kSolid ? b : -1;
            if (npc < 0) continue;
            for (int c = 0; c < manifold.getNumContacts(); ++c)
                if (manifold.getContactPoint(c).getDistance() < kTouching) now[static_cast<std::size_t>(npc)] = true;
        }
        for (std::size_t i = 0; i < bodies_.size(); ++i)
            if (now[i]) touchedThisStep_[i] = true;
    }
    // A collision is an agent step in contact after one without: a capsule sliding along a wall
    // makes and breaks contact between sub-steps, and that is one scrape, not many.
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (touchedThisStep_[i] && !touching_[i]) ++totals_.collisions;
        touching_[i] = touchedThisStep_[i];
    }
}

void RayNpcScene::reward() {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const Vec2 p = position(i);
        const double toTarget = distance(p, targets_[i]);
        double r = config_.progressReward * (targetDistance_[i] - toTarget);
        targetDistance_[i] = toTarget;
        if (toTarget < config_.reachRadius) {
            targets_[i] = newTarget(i);
            targetDistance_[i] = distance(p, targets_[i]);  // a new target counts from here
            ++totals_.targets;
            r += 1.0;
        }
        if (layout_->inHazard(p)) {
            totals_.hazardSeconds += config_.agentStep;
            r -= 1.0;
        }
        if (touchedThisStep_[i]) r -= config_.collisionPenalty;
        rewards_[i] = static_cast<float>(std::clamp(r, -1.0, 1.0));
        totals_.reward += rewards_[i];
    }
}

void RayNpcScene::step() {
    act();
    simulate();
    reward();
    time_ += config_.agentStep;
    totals_.seconds += config_.agentStep;
}

RayNpcStats RayNpcScene::run(double seconds) {
    const RayNpcStats before = totals_;
    const std::uint32_t steps = stepsIn(seconds, config_.agentStep);
    for (std::uint32_t s = 0; s < steps; ++s) step();
    RayNpcStats out = totals_;
    out.seconds -= before.seconds;
    out.targets -= before.targets;
    out.hazardSeconds -= before.hazardSeconds;
    out.collisions -= before.collisions;
    out.reward -= before.reward;
    return out;
}

}  // namespace verve::scenes
