// Learning NPCs: a walled arena where capsule bodies, each with its own agent, learn to reach
// food and keep out of a hazard zone. Sensors are egocentric: the bearing (circular) and distance
// to the nearest food, and a discrete hazard sensor (clear / hazard ahead / inside the hazard).
// Rewards: +1 for eating, -1 for every step inside the hazard, 0 otherwise.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "scene_random.hpp"
#include "verve/agent.hpp"
#include "verve/batch.hpp"

class btRigidBody;

namespace verve::scenes {

class PhysicsWorld;

struct NpcArenaConfig {
    std::uint32_t npcs = 8;
    std::uint32_t food = 3;          // items on the floor; an eaten one reappears elsewhere
    float halfSize = 5.0f;           // m; walls at +-halfSize on x and z
    float hazardRadius = 1.6f;       // m; a disc at the arena centre
    float eatRadius = 0.5f;          // m from an NPC's centre
    float aheadDistance = 1.2f;      // m; where the hazard sensor looks
    float speed = 2.0f;              // m/s reached under full thrust (drag balances it)
    float turnRate = 3.0f;           // rad/s reached under full torque
    float physicsStep = 0.01f;       // s
    float agentStep = 0.1f;          // s
    bool sharedBrain = false;        // every NPC a body of one brain (verve/brain.hpp), not its own agent
    // The agents step in one verve::Batch call per agent step, as a game with a crowd would: a
    // shared brain's bodies then act in the batch's phases (docs/crowds.md).
    bool batch = false;
};

// Totals over a stretch of simulated time, summed over all NPCs.
struct ArenaStats {
    double seconds = 0.0;
    std::uint32_t npcs = 0;
    std::uint32_t foodEaten = 0;
    double hazardSeconds = 0.0;

    double foodPerNpcMinute() const { return foodEaten / (npcs * seconds / 60.0); }
    double hazardFraction() const { return hazardSeconds / (npcs * seconds); }
};

class NpcArena {
public:
    enum Action : std::uint32_t { Forward = 0, TurnLeft = 1, TurnRight = 2 };
    enum Hazard : std::int32_t { Clear = 0, Ahead = 1, Inside = 2 };

    // Every NPC gets an agent built from `agents` with its own seed drawn from `seed`, which also
    // decides where NPCs start and food appears: the same seed, the same run. With sharedBrain,
    // the NPCs are bodies of one brain seeded with NPC 0's seed (the same draws either way).
    NpcArena(const NpcArenaConfig& config, std::uint64_t seed,
             const AgentDescriptor& agents = defaultDescriptor());
    ~NpcArena();

    static AgentDescriptor defaultDescriptor();

    // Who drives the NPCs: their agents (the default); the designer's scripted steering, with the
    // agents learning from it as demonstrations (docs/teaching.md); or the script alone.
    enum class Driver { Agents, ScriptDemonstrates, Script };
    void setDriver(Driver driver) { driver_ = driver; }
    // A designer's steering, as a game would script it: turn away from the hazard ahead, turn toward
    // the food until it lies within about 27 degrees of the heading, then walk.
    static std::uint32_t scriptedAction(const Observation& obs);

    // One agent step for every NPC: sense, decide, push, simulate, reward.
    void step();
    // Steps for `seconds` of simulated time and returns what happened in it.
    ArenaStats run(double seconds);

    std::size_t npcCount() const { return agents_.size(); }
    const Agent& agent(std::size_t i) const { return agents_.at(i); }
    Agent& agent(std::size_t i) { return agents_.at(i); }
    void observe(std::size_t npc, Observation& out) const;
    const NpcArenaConfig& config() const { return config_; }
    double time() const { return time_; }

private:
    struct Vec2 {
        double x = 0, z = 0;
    };
    Vec2 position(std::size_t npc) const;
    Vec2 heading(std::size_t npc) const;
    bool inHazard(Vec2 p) const;
    Vec2 freeSpot();
    std::size_t nearestFood(Vec2 p) const;

    NpcArenaConfig config_;
    SceneRandom random_;
    std::unique_ptr<PhysicsWorld> world_;
    std::vector<btRigidBody*> bodies_;  // owned by world_
    std::vector<Agent> agents_;
    std::vector<float> rewards_;        // what each NPC's previous action earned
    std::vector<Vec2> food_;
    std::vector<std::uint32_t> actions_;
    Observation scratch_;
    // With config.batch: the batch, and its packed sensor values.
    std::unique_ptr<Batch> batch_;
    std::vector<Agent*> batchAgents_;
    std::vector<std::int32_t> packedDiscrete_;
    std::vector<float> packedContinuous_;
    void stepBatch();
    double time_ = 0.0;
    ArenaStats totals_;
    Driver driver_ = Driver::Agents;
};

}  // namespace verve::scenes
