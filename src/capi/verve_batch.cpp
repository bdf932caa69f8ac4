// Many agents in one call: verve_batch over verve::Batch (its own pool or the host's job system).
#include <algorithm>
#include <atomic>
#include <string>
#include <vector>

#include "capi/capi_agent.hpp"
#include "capi/capi_in_use.hpp"
#include "verve/batch.hpp"

struct verve_batch {
    explicit verve_batch(const verve::BatchOptions& options) : batch(options) {}
    verve::Batch batch;
    // Held by every call on the batch: verve_batch_destroy refuses while one runs.
    verve::capi::InUseFlag inUse{false};
    // Scratch reused from call to call: the agents behind the handles, the per-agent verdicts.
    std::vector<verve::Agent*> agents;
    std::vector<verve::capi::InUseFlag*> held;        // the in-use flags this call holds: its agents'
    std::vector<verve::capi::InUseFlag*> heldBrains;  // and their brains' (capi_in_use.hpp)
    std::vector<int> results;
};

namespace {

using verve::capi::guarded;
using verve::capi::requireArg;

verve_batch_desc defaultBatchDesc() {
    verve_batch_desc d{};
    d.struct_size = sizeof d;
    return d;
}

verve::BatchOptions toOptions(const verve_batch_desc& d) {
    if (d.struct_size != sizeof(verve_batch_desc)) {
        throw verve::Error(verve::ErrorCode::InvalidArgument,
                           "desc->struct_size is " + std::to_string(d.struct_size) + ", expected sizeof(verve_batch_desc) = " +
                               std::to_string(sizeof(verve_batch_desc)) + "; fill it with verve_batch_desc_default");
    }
    verve::BatchOptions o;
    o.workerCount = d.worker_count;
    // verve_task_fn and verve::TaskFunction are the same C signature (cdecl on every target).
    o.scheduler.enqueueTask = d.enqueue_task;
    o.scheduler.finishTask = d.finish_task;
    o.scheduler.userContext = d.user_context;
    return o;
}

}  // namespace

extern "C" {

VERVE_API verve_result VERVE_CALL verve_batch_desc_default(verve_batch_desc* desc) {
    return guarded(__func__, [&] {
        requireArg(desc, "desc");
        *desc = defaultBatchDesc();
    });
}

VERVE_API verve_result VERVE_CALL verve_batch_create(const verve_batch_desc* desc, verve_batch** out) {
    return guarded(__func__, [&] {
        requireArg(desc, "desc");
        requireArg(out, "out");
        *out = new verve_batch(toOptions(*desc));
    });
}

VERVE_API void VERVE_CALL verve_batch_destroy(verve_batch* batch) {
    if (batch == nullptr) return;
    // Freeing a batch a call is inside (its workers running) would crash that call: it stays alive.
    if (!verve::capi::tryAcquire(batch->inUse)) {
        verve::capi::recordError(__func__, VERVE_ERROR_INVALID_STATE, "the batch is in use by another call: not destroyed");
        return;
    }
    delete batch;
}

VERVE_API verve_result VERVE_CALL verve_batch_get_worker_count(const verve_batch* batch, uint32_t* out_count) {
    return guarded(__func__, [&] {
        requireArg(batch, "batch");
        requireArg(out_count, "out_count");
        // Read-only and fixed at creation: no in-use flag needed.
        *out_count = batch->batch.workerCount();
    });
}

namespace {

// What the host showed the agents of a call: actions NULL, every agent chooses; continuous NULL,
// a demonstrated step plays the policy's means.
struct Shown {
    const uint32_t* actions = nullptr;
    const float* continuous = nullptr;
    const uint32_t* continuousOffsets = nullptr;
    uint32_t continuousTotal = 0;
};

// verve_batch_update and the calls with demonstrated steps.
verve_result batchUpdate(const char* function, verve_batch* batch, verve_agent* const* agents, uint32_t n,
                         const float* rewards, const int32_t* discrete, const uint32_t* discrete_offsets,
                         uint32_t discrete_total, const float* continuous, const uint32_t* continuous_offsets,
                         uint32_t continuous_total, float dt, const Shown& shown, uint32_t* out_actions,
                         verve_result* out_results) {
    bool verdicts = false;  // out_results holds each agent's verdict from verve::Batch
    const verve_result result = guarded(function, [&] {
        requireArg(batch, "batch");
        if (n == 0) return;
        requireArg(agents, "agents");
        requireArg(rewards, "rewards");
        requireArg(out_actions, "out_actions");
        // The batch's own flag first (its scratch is used by one call at a time); then room (InUse
        // records every flag it takes within this capacity) for each agent's and each body's
        // brain's, held for the whole call as a single call holds them; an agent or brain listed
        // twice is taken once.
        verve::capi::InUse batchUse;
        batchUse.take(batch->inUse);
        batch->held.reserve(n);
        batch->heldBrains.reserve(n);
        verve::capi::InUse use(batch->held, batch->heldBrains);
        batch->agents.resize(n);
        batch->results.assign(n, 0);
        for (uint32_t i = 0; i < n; ++i) {
            verve_agent* h = agents[i];
            batch->agents[i] = nullptr;
            if (h == nullptr) continue;  // refused below, naming the agent
            use.take(h->inUse);
            if (h->brainInUse != nullptr) use.takeShared(*h->brainInUse);
            // Through mutableAgent: an update drops the saves that verve_agent_save_memory keeps.
            batch->agents[i] = &h->mutableAgent();
        }
        verve::BatchStep step;
        step.agents = batch->agents.data();
        step.count = n;
        step.rewards = rewards;
        step.discrete = discrete;
        step.discreteOffsets = discrete_offsets;
        step.discreteTotal = discrete_total;
        step.continuous = continuous;
        step.continuousOffsets = continuous_offsets;
        step.continuousTotal = continuous_total;
        step.dt = dt;
        step.demonstrated = shown.actions;
        step.demonstratedContinuous = shown.continuous;
        step.demonstratedContinuousOffsets = shown.continuousOffsets;
        step.demonstratedContinuousTotal = shown.continuousTotal;
        step.actions = out_actions;
        step.results = batch->results.data();
        try {
            batch->batch.update(step);
        } catch (...) {
            // verve::Batch wrote every agent's verdict, a refusal of the whole call included.
            if (out_results != nullptr) {
                for (uint32_t i = 0; i < n; ++i) {
                    const int code = batch->results[i];
                    out_results[i] = code == 0 ? VERVE_OK : verve::capi::toResult(static_cast<verve::ErrorCode>(code));
                }
                verdicts = true;
            }
            throw;
        }
        if (out_results != nullptr) {
            for (uint32_t i = 0; i < n; ++i) out_results[i] = VERVE_OK;
        }
    });
    // Refused before verve::Batch saw the call (NULL arrays, a handle in use by another call):
    // no agent was updated, and every verdict says why (never VERVE_OK, never stale).
    if (result != VERVE_OK && !verdicts && out_results != nullptr) {
        for (uint32_t i = 0; i < n; ++i) out_results[i] = result;
    }
    return result;
}

}  // namespace

VERVE_API verve_result VERVE_CALL verve_batch_update(verve_batch* batch, verve_agent* const* agents, uint32_t n,
                                                     const float* rewards, const int32_t* discrete,
                                                     const uint32_t* discrete_offsets, uint32_t discrete_total,
                                                     const float* continuous, const uint32_t* continuous_offsets,
                                                     uint32_t continuous_total, float dt, uint32_t* out_actions,
                                                     verve_result* out_results) {
    return batchUpdate(__func__, batch, agents, n, rewards, discrete, discrete_offsets, discrete_total, continuous,
                       continuous_offsets, continuous_total, dt, Shown{}, out_actions, out_results);
}

VERVE_API verve_result VERVE_CALL verve_batch_update_demonstrated(
    verve_batch* batch, verve_agent* const* agents, uint32_t n, const float* rewards, const int32_t* discrete,
    const uint32_t* discrete_offsets, uint32_t discrete_total, const float* continuous,
    const uint32_t* continuous_offsets, uint32_t continuous_total, float dt, const uint32_t* demonstrated,
    uint32_t* out_actions, verve_result* out_results) {
    return batchUpdate(__func__, batch, agents, n, rewards, discrete, discrete_offsets, discrete_total, continuous,
                       continuous_offsets, continuous_total, dt, Shown{demonstrated}, out_actions, out_results);
}

VERVE_API verve_result VERVE_CALL verve_batch_update_demonstrated_continuous(
    verve_batch* batch, verve_agent* const* agents, uint32_t n, const float* rewards, const int32_t* discrete,
    const uint32_t* discrete_offsets, uint32_t discrete_total, const float* continuous,
    const uint32_t* continuous_offsets, uint32_t continuous_total, float dt, const uint32_t* demonstrated,
    const float* continuous_actions, const uint32_t* continuous_action_offsets, uint32_t continuous_actions_total,
    uint32_t* out_actions, verve_result* out_results) {
    const Shown shown{demonstrated, continuous_actions, continuous_action_offsets, continuous_actions_total};
    return batchUpdate(__func__, batch, agents, n, rewards, discrete, discrete_offsets, discrete_total, continuous,
                       continuous_offsets, continuous_total, dt, shown, out_actions, out_results);
}

}  // extern "C"
