// Raycast NPCs: capsule bodies in a walled, cluttered arena see the world as a game NPC does,
// through a fan of Bullet ray tests, and learn to fetch a target item while keeping out of a hazard
// zone and off the walls. The NPC arena's (npc_arena.hpp) bigger sibling: 12 continuous sensors at
// default instead of 2, for agents with many sensors (docs/scenes.md, "ray-npc").
//
// Sensors (all egocentric; docs/scenes.md lists them):
//   discrete 0:        hazard: clear / hazard ahead / inside (the hazard is a floor zone, which
//                      rays that stop at solid things cannot see, so it has its own sensor as in the
//                      NPC arena)
//   continuous 0..N-1: ray distances, right (-90 deg) to left (+90 deg) over the front half:
//                      -1 touching, +1 nothing within rayRange of the NPC's surface
//   continuous N:      bearing to the NPC's target (circular, / 180 deg, positive to the left)
//   continuous N+1:    distance to it (/ the arena's diagonal)
//   continuous N+2:    forward speed (/ speed)
//   continuous N+3:    turn rate (/ turnRate, positive turning left)
// Rewards: +1 on reaching the target (a new one appears elsewhere), -1 per agent step inside the
// hazard, -collisionPenalty per agent step touching a wall or an obstacle, progressReward per metre
// closed on the target (0 by default); summed, within [-1, 1].
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "ray_npc_layout.hpp"
#include "scene_random.hpp"
#include "verve/agent.hpp"

class btRigidBody;

namespace verve::scenes {

class PhysicsWorld;

struct RayNpcConfig {
    std::uint32_t npcs = 4;
    // Rays over the front half: an NPC only walks forward and turns in place, and a capsule that
    // turns cannot hit anything, so what lies behind it never decides a collision; eight rays over
    // 180 degrees are 25.7 degrees apart, fine enough to see a 0.6 m box within 1.3 m.
    std::uint32_t rays = 8;          // 8..16
    float rayArc = 3.14159265f;      // rad, centred on the heading
    float rayRange = 3.0f;           // m from the NPC's surface
    RayNpcLayoutConfig layout;
    float reachRadius = 0.5f;        // m from an NPC's centre to its target
    float aheadDistance = 1.2f;      // m; where the hazard sensor looks
    float speed = 2.0f;              // m/s reached under full thrust (drag balances it)
    float turnRate = 3.0f;           // rad/s reached under full torque
    // Scraping along a wall costs time but nothing else; a small price makes the agent learn what
    // a player would call clumsy, without drowning the +1 of a target (10 s of contact = 1 target).
    float collisionPenalty = 0.1f;
    // Reward per metre the NPC closed on its target during the step (negative when it walked away):
    // what a designer adds when arrival alone is too rare to learn from. It is shaping by a
    // potential (minus the distance): its sum over a walk depends only on where the walk began and
    // ended, so circling earns nothing and the best way to the target stays the best (Ng, Harada
    // and Russell 1999).
    // 0 by default: the scene as first measured, arrival only (docs/scenes.md, "ray-npc").
    float progressReward = 0.0f;
    float physicsStep = 0.01f;       // s
    float agentStep = 0.1f;          // s
    bool sharedBrain = false;        // every NPC a body of one brain (verve/brain.hpp), not its own agent
};

// Totals over a stretch of simulated time, summed over all NPCs.
struct RayNpcStats {
    double seconds = 0.0;
    std::uint32_t npcs = 0;
    std::uint32_t targets = 0;      // targets reached
    double hazardSeconds = 0.0;
    std::uint32_t collisions = 0;   // agent steps touching a wall or an obstacle after one that did not
    double reward = 0.0;            // the rewards the agents were given

    double npcMinutes() const { return npcs * seconds / 60.0; }
    double targetsPerNpcMinute() const { return targets / npcMinutes(); }
    double hazardFraction() const { return hazardSeconds / (npcs * seconds); }
    double collisionsPerNpcMinute() const { return collisions / npcMinutes(); }
    double rewardPerNpcMinute() const { return reward / npcMinutes(); }
};

class RayNpcScene {
public:
    enum Action : std::uint32_t { Forward = 0, TurnLeft = 1, TurnRight = 2, ForwardLeft = 3, ForwardRight = 4 };
    static constexpr std::uint32_t kActions = 5;
    enum Hazard : std::int32_t { Clear = 0, Ahead = 1, Inside = 2 };

    // The seed decides the layout, where NPCs start, where targets appear and every agent's seed
    // (drawn in that order, whoever drives): the same seed, the same run.
    RayNpcScene(const RayNpcConfig& config, std::uint64_t seed);
    RayNpcScene(const RayNpcConfig& config, std::uint64_t seed, const AgentDescriptor& agents);
    ~RayNpcScene();

    // The sensors and actions above, every learning setting at the library's default.
    static AgentDescriptor defaultDescriptor(const RayNpcConfig& config = {});
    static std::uint32_t continuousSensors(const RayNpcConfig& config) { return config.rays + 4; }
    // Ray i's direction, rad from the heading, positive to the left: evenly over the arc, its ends
    // included (a full circle leaves out the end that would repeat the start).
    static double rayAngle(const RayNpcConfig& config, std::uint32_t i);

    // Who drives the NPCs: their agents; the scripted steering (ray_npc_steering.hpp) with the
    // agents learning from it as demonstrations (docs/teaching.md); or the script alone.
    enum class Driver { Agents, ScriptDemonstrates, Script };
    void setDriver(Driver driver) { driver_ = driver; }

    // One agent step for every NPC: sense, decide, push, simulate, reward.
    void step();
    // Steps for `seconds` of simulated time and returns what happened in it.
    RayNpcStats run(double seconds);

    std::size_t npcCount() const { return agents_.size(); }
    const Agent& agent(std::size_t i) const { return agents_.at(i); }
    Agent& agent(std::size_t i) { return agents_.at(i); }
    void observe(std::size_t npc, Observation& out) const;
    const RayNpcConfig& config() const { return config_; }
    const RayNpcLayout& layout() const { return *layout_; }
    Vec2 position(std::size_t npc) const;
    Vec2 heading(std::size_t npc) const;  // unit vector on the floor
    Vec2 target(std::size_t npc) const { return targets_.at(npc); }
    double time() const { return time_; }
    std::uint32_t lastAction(std::size_t npc) const { return actions_.at(npc); }

private:
    void buildWorld();
    void act();
    void simulate();
    void reward();
    Vec2 newTarget(std::size_t npc);
    // Distance from the NPC's surface to the first solid thing along `angle` (rad, positive to
    // the left of the heading), at most rayRange.
    double castRay(std::size_t npc, double angle) const;

    RayNpcConfig config_;
    SceneRandom random_;
    std::unique_ptr<RayNpcLayout> layout_;
    std::unique_ptr<PhysicsWorld> world_;
    std::vector<btRigidBody*> bodies_;  // owned by world_
    std::vector<Agent> agents_;
    std::vector<Vec2> targets_;
    std::vector<float> rewards_;        // what each NPC's previous action earned
    std::vector<std::uint32_t> actions_;
    std::vector<bool> touchedThisStep_; // in contact with a wall or obstacle during the agent step
    std::vector<bool> touching_;        // ... during the previous one
    std::vector<double> targetDistance_; // from each NPC to its target after the previous step
    Observation scratch_;
    double time_ = 0.0;
    RayNpcStats totals_;
    Driver driver_ = Driver::Agents;
};

}  // namespace verve::scenes
