// Many agents in one call: Batch::update steps N agents (any shapes, separate or bodies of shared
// brains) and spreads them over worker threads, on a pool of its own or on the host's job system.
//
// Results are the same for any number of threads. Separate agents get exactly the results of
// Agent::update on each in array order (agents that share nothing run in parallel). The bodies of
// one brain also run in parallel, in phases: each acts against the brain as the call found it
// (plus its own learning step), then their weight changes are applied in array order; a step that
// grows the brain is made whole afterwards. A brain that plans, or whose bodies include one listed
// twice or shown an action, keeps single updates' results: its bodies run in array order on one
// worker. docs/crowds.md, "Bodies in parallel".
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>

#include "verve/agent.hpp"
#include "verve/observation.hpp"

namespace verve {

// A range of work items [begin, end) run by worker `worker` (< the scheduler's worker count).
using TaskFunction = void (*)(std::uint32_t begin, std::uint32_t end, std::uint32_t worker, void* taskContext);

// A host's job system, the way Box2D v3's b2WorldDef takes one. enqueueTask runs `task` over
// [0, itemCount) in ranges of at least minRange items, on any workers, and returns a handle that
// finishTask waits on; returning nullptr means the task already ran (inline), and finishTask is
// not called for it. Both are called only from the thread that called Batch::update.
struct TaskScheduler {
    void* (*enqueueTask)(TaskFunction task, std::uint32_t itemCount, std::uint32_t minRange, void* taskContext,
                         void* userContext) = nullptr;
    void (*finishTask)(void* userTask, void* userContext) = nullptr;
    void* userContext = nullptr;
};

struct BatchOptions {
    // Threads working on a batch, the caller included. 0: the machine's hardware threads.
    // With a scheduler: the host's worker count (worker indices it passes are below it).
    std::uint32_t workerCount = 0;
    TaskScheduler scheduler;  // both callbacks set: the host's job system; both null: Verve's own pool
};

// BatchStep::demonstrated's "no demonstration: the agent chooses".
inline constexpr std::uint32_t kAgentChooses = 0xFFFFFFFFu;

// One step of N agents, from packed arrays (structure-of-arrays, as an engine keeps its NPCs).
// Agent i reads rewards[i], and its discrete and continuous sensor values from `discrete` and
// `continuous`: at discreteOffsets[i] / continuousOffsets[i] when those are given, otherwise right
// after agent i-1's values (packed back to back). The totals are the arrays' lengths.
struct BatchStep {
    Agent* const* agents = nullptr;
    std::size_t count = 0;
    const float* rewards = nullptr;
    const std::int32_t* discrete = nullptr;
    const std::uint32_t* discreteOffsets = nullptr;
    std::size_t discreteTotal = 0;
    const float* continuous = nullptr;
    const std::uint32_t* continuousOffsets = nullptr;
    std::size_t continuousTotal = 0;
    float dt = 0.0f;                  // seconds since the previous step, the same for all
    // Optional: demonstrated[i] is the action the host took for agent i (a demonstrated step,
    // Agent::updateDemonstrated), or kAgentChooses for the agent's own choice.
    const std::uint32_t* demonstrated = nullptr;
    // Optional, with `demonstrated`: the continuous actions the host played (the overload of
    // Agent::updateDemonstrated that takes them). Agent i's descriptor().continuousActions values
    // lie at demonstratedContinuousOffsets[i] when given, otherwise right after agent i-1's (every
    // agent's count, shown or not, packed back to back); they are read only for an agent shown an
    // action. Null: a demonstrated step plays the policy's means, as without the values.
    const float* demonstratedContinuous = nullptr;
    const std::uint32_t* demonstratedContinuousOffsets = nullptr;
    std::size_t demonstratedContinuousTotal = 0;
    std::uint32_t* actions = nullptr; // out: agent i's action (the demonstrated one, if any)
    int* results = nullptr;           // optional out: per agent 0 (fine) or the ErrorCode of its failure
};

class Batch {
public:
    explicit Batch(const BatchOptions& options = {});  // throws Error(InvalidArgument)
    ~Batch();  // joins the pool's threads
    Batch(const Batch&) = delete;
    Batch& operator=(const Batch&) = delete;

    // Validates every input first: on any bad one it throws Error naming the first (e.g.
    // "agents[3]: ..."), fills `results` and changes no agent. Then updates all of them. An update
    // that still fails (out of memory) leaves that agent unchanged and the others updated, and is
    // thrown after all of them ran. The pool's threads start on the first call.
    void update(const BatchStep& step);

    std::uint32_t workerCount() const;

    struct Impl;  // internal (src/core/batch.cpp)

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace verve
