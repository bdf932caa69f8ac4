#include "npc_arena.hpp"

#include <cmath>
#include <limits>

#include "physics_world.hpp"
#include "scene_util.hpp"
#include "verve/brain.hpp"

namespace verve::scenes {

namespace {
constexpr btScalar kRadius = 0.3f;       // capsule
constexpr btScalar kHeight = 0.6f;       // capsule's cylinder part
constexpr btScalar kMass = 1.0f;
constexpr btScalar kDrag = 0.99f;        // Bullet damping: velocity keeps (1 - d)^t per second
constexpr btScalar kWallThickness = 0.5f;

// Bullet damping multiplies velocity by (1 - d)^dt: an exponential decay at this rate (1/s).
double dragRate() { return -std::log(1.0 - static_cast<double>(kDrag)); }

void addWall(PhysicsWorld& world, const btVector3& halfExtents, const btVector3& centre) {
    btTransform t;
    t.setIdentity();
    t.setOrigin(centre);
    world.addBody(std::make_unique<btBoxShape>(halfExtents), 0, t);
}
}  // namespace

NpcArena::NpcArena(const NpcArenaConfig& config, std::uint64_t seed, const AgentDescriptor& agents)
    : config_(config), random_(seed), world_(std::make_unique<PhysicsWorld>()) {
    if (config.npcs == 0 || config.food == 0 || config.halfSize <= config.hazardRadius + 1.0f)
        throw Error(ErrorCode::InvalidArgument,
                    "npc arena: needs at least one NPC and one food item, and room around the hazard");
    agents.validate();
    if (agents.discreteSensors != std::vector<std::uint32_t>{3} || agents.continuousSensors.size() != 2 ||
        agents.numActions != 3)
        throw Error(ErrorCode::InvalidArgument,
                    "npc arena: agents need sensors {hazard(3)} + {bearing, distance} and 3 actions");

    std::unique_ptr<Brain> brain;  // with sharedBrain; its bodies keep it alive
    const btScalar h = config.halfSize;
    btTransform floor;
    floor.setIdentity();
    world_->addBody(std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), 0), 0, floor);
    addWall(*world_, btVector3(kWallThickness, 1, h), btVector3(h + kWallThickness, 1, 0));
    addWall(*world_, btVector3(kWallThickness, 1, h), btVector3(-h - kWallThickness, 1, 0));
    addWall(*world_, btVector3(h, 1, kWallThickness), btVector3(0, 1, h + kWallThickness));
    addWall(*world_, btVector3(h, 1, kWallThickness), btVector3(0, 1, -h - kWallThickness));

    for (std::uint32_t i = 0; i < config.npcs; ++i) {
        const Vec2 p = freeSpot();
        btTransform t;
        t.setIdentity();
        t.setOrigin(btVector3(static_cast<btScalar>(p.x), kRadius + kHeight / 2, static_cast<btScalar>(p.z)));
        t.setRotation(btQuaternion(btVector3(0, 1, 0), static_cast<btScalar>(random_.uniform(-kPi, kPi))));
        btRigidBody* body = world_->addBody(std::make_unique<btCapsuleShape>(kRadius, kHeight), kMass, t);
        body->setAngularFactor(btVector3(0, 1, 0));  // stays upright, only turns
        body->setDamping(kDrag, kDrag);
        bodies_.push_back(body);

        AgentDescriptor d = agents;
        d.seed = static_cast<std::uint64_t>(random_.uniform(0, 0x1.0p53));
        addNpcAgent(agents_, brain, d, config.sharedBrain);
    }
    for (std::uint32_t i = 0; i < config.food; ++i) food_.push_back(freeSpot());
    rewards_.assign(config.npcs, 0.0f);
    actions_.assign(config.npcs, Forward);
    scratch_ = Observation(agents);
    if (config.batch) {
        batch_ = std::make_unique<Batch>();
        for (Agent& a : agents_) batchAgents_.push_back(&a);
    }
}

NpcArena::~NpcArena() = default;

AgentDescriptor NpcArena::defaultDescriptor() {
    AgentDescriptor d;
    d.addDiscreteSensor(3);        // hazard: clear, ahead, inside
    d.addContinuousSensor(true);   // bearing to the nearest food, circular
    d.addContinuousSensor(false);  // distance to it
    d.numActions = 3;
    d.resolution = 8;
    d.tauDiscount = 2.0f;  // food is a few seconds away: look further ahead than the default 1 s
    d.tauEligibility = 0.3f;
    return d;
}

NpcArena::Vec2 NpcArena::position(std::size_t npc) const {
    const btVector3 p = bodies_[npc]->getCenterOfMassPosition();
    return {p.x(), p.z()};
}

NpcArena::Vec2 NpcArena::heading(std::size_t npc) const {
    const btVector3 f = bodies_[npc]->getWorldTransform().getBasis().getColumn(0);  // local +x
    const double len = std::hypot(static_cast<double>(f.x()), static_cast<double>(f.z()));
    return {f.x() / len, f.z() / len};
}

bool NpcArena::inHazard(Vec2 p) const { return std::hypot(p.x, p.z) < config_.hazardRadius; }

NpcArena::Vec2 NpcArena::freeSpot() {
    const double edge = config_.halfSize - 0.5;
    for (;;) {
        const Vec2 p{random_.uniform(-edge, edge), random_.uniform(-edge, edge)};
        if (std::hypot(p.x, p.z) > config_.hazardRadius + 0.5) return p;
    }
}

std::size_t NpcArena::nearestFood(Vec2 p) const {
    std::size_t best = 0;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < food_.size(); ++i) {
        const double d = std::hypot(food_[i].x - p.x, food_[i].z - p.z);
        if (d < bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    return best;
}

void NpcArena::observe(std::size_t npc, Observation& out) const {
    const Vec2 p = position(npc);
    const Vec2 f = heading(npc);
    const Vec2 food = food_[nearestFood(p)];
    const Vec2 to{food.x - p.x, food.z - p.z};
    const Vec2 ahead{p.x + f.x * config_.aheadDistance, p.z + f.z * config_.aheadDistance};
    const std::int32_t hazard = inHazard(p) ? Inside : inHazard(ahead) ? Ahead : Clear;
    // Bearing: signed angle from the heading to the food, positive toward a left turn.
    const double bearing = std::atan2(f.x * to.z - f.z * to.x, f.x * to.x + f.z * to.z);
    const double diagonal = 2.0 * std::sqrt(2.0) * config_.halfSize;
    out.discrete.assign({hazard});
    out.continuous.assign({toSensor(bearing, kPi),
                           static_cast<float>(2.0 * std::hypot(to.x, to.z) / diagonal - 1.0)});
}

std::uint32_t NpcArena::scriptedAction(const Observation& obs) {
    constexpr float kAligned = 0.15f;  // of pi: about 27 degrees
    const float bearing = obs.continuous.at(0);  // positive toward a left turn
    if (bearing > kAligned) return TurnLeft;
    if (bearing < -kAligned) return TurnRight;
    return Forward;
}

void NpcArena::stepBatch() {
    packedDiscrete_.clear();
    packedContinuous_.clear();
    for (std::size_t i = 0; i < agents_.size(); ++i) {
        observe(i, scratch_);
        packedDiscrete_.insert(packedDiscrete_.end(), scratch_.discrete.begin(), scratch_.discrete.end());
        packedContinuous_.insert(packedContinuous_.end(), scratch_.continuous.begin(), scratch_.continuous.end());
    }
    BatchStep s;
    s.agents = batchAgents_.data();
    s.count = batchAgents_.size();
    s.rewards = rewards_.data();
    s.discrete = packedDiscrete_.data();
    s.discreteTotal = packedDiscrete_.size();
    s.continuous = packedContinuous_.data();
    s.continuousTotal = packedContinuous_.size();
    s.dt = config_.agentStep;
    s.actions = actions_.data();
    batch_->update(s);
}

void NpcArena::step() {
    if (batch_ && driver_ == Driver::Agents) {
        stepBatch();
    } else {
        for (std::size_t i = 0; i < agents_.size(); ++i) {
            observe(i, scratch_);
            if (driver_ == Driver::Agents) {
                actions_[i] = agents_[i].update(rewards_[i], scratch_, config_.agentStep);
            } else {
                actions_[i] = scriptedAction(scratch_);
                if (driver_ == Driver::ScriptDemonstrates) {
                    agents_[i].updateDemonstrated(rewards_[i], scratch_.view(), config_.agentStep, actions_[i]);
                }
            }
        }
    }
    // Full thrust or torque balances the drag at the configured speed or turn rate.
    const btScalar thrust = static_cast<btScalar>(kMass * dragRate() * config_.speed);
    advance(*world_, config_.agentStep, config_.physicsStep, [&] {
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            btRigidBody& body = *bodies_[i];
            const Vec2 f = heading(i);
            const btScalar inertia = 1 / body.getInvInertiaDiagLocal().y();
            const btScalar torque = static_cast<btScalar>(inertia * dragRate() * config_.turnRate);
            // Local +x turning toward +z is a negative turn about y; "left" matches a positive bearing.
            switch (actions_[i]) {
                case Forward:
                    body.applyCentralForce(btVector3(static_cast<btScalar>(f.x) * thrust, 0,
                                                     static_cast<btScalar>(f.z) * thrust));
                    break;
                case TurnLeft: body.applyTorque(btVector3(0, -torque, 0)); break;
                default: body.applyTorque(btVector3(0, torque, 0)); break;
            }
        }
    });
    time_ += config_.agentStep;

    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const Vec2 p = position(i);
        float reward = 0.0f;
        const std::size_t nearest = nearestFood(p);
        if (std::hypot(food_[nearest].x - p.x, food_[nearest].z - p.z) < config_.eatRadius) {
            food_[nearest] = freeSpot();
            ++totals_.foodEaten;
            reward = 1.0f;
        }
        if (inHazard(p)) {
            totals_.hazardSeconds += config_.agentStep;
            reward = -1.0f;
        }
        rewards_[i] = reward;
    }
    totals_.seconds += config_.agentStep;
}

ArenaStats NpcArena::run(double seconds) {
    const ArenaStats before = totals_;
    const std::uint32_t steps = stepsIn(seconds, config_.agentStep);
    for (std::uint32_t s = 0; s < steps; ++s) step();
    ArenaStats out;
    out.npcs = static_cast<std::uint32_t>(bodies_.size());
    out.seconds = totals_.seconds - before.seconds;
    out.foodEaten = totals_.foodEaten - before.foodEaten;
    out.hazardSeconds = totals_.hazardSeconds - before.hazardSeconds;
    return out;
}

}  // namespace verve::scenes
