// Many agents in one call: verve_batch over verve::Batch (its own pool or the host's job system).
#include <algorithm>
#include <atomic>
#include <string>
#include <vector>

#include "capi/capi_agent.hpp"
#include "verve/batch.hpp"

struct verve_batch {
    explicit verve_batch(const verve::BatchOptions& options) : batch(options) {}
    verve::Batch batch;
    // Scratch reused from call to call: the agents behind the handles, the per-agent verdicts.
    std::vector<verve::Agent*> agents;
    std::vector<verve_agent*> held;  // the handles whose in-use flag this call holds
    std::vector<std::atomic<bool>*> heldBrains;  // and the flags of their bodies' brains
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

VERVE_API void VERVE_CALL verve_batch_destroy(verve_batch* batch) { delete batch; }

VERVE_API verve_result VERVE_CALL verve_batch_get_worker_count(const verve_batch* batch, uint32_t* out_count) {
    return guarded(__func__, [&] {
        requireArg(batch, "batch");
        requireArg(out_count, "out_count");
        *out_count = batch->batch.workerCount();
    });
}

VERVE_API verve_result VERVE_CALL verve_batch_update(verve_batch* batch, verve_agent* const* agents, uint32_t n,
                                                     const float* rewards, const int32_t* discrete,
                                                     const uint32_t* discrete_offsets, uint32_t discrete_total,
                                                     const float* continuous, const uint32_t* continuous_offsets,
                                                     uint32_t continuous_total, float dt, uint32_t* out_actions,
                                                     verve_result* out_results) {
    return guarded(__func__, [&] {
        requireArg(batch, "batch");
        if (n == 0) return;
        requireArg(agents, "agents");
        requireArg(rewards, "rewards");
        requireArg(out_actions, "out_actions");
        batch->agents.resize(n);
        batch->results.assign(n, 0);
        // Room first: a flag once taken is always recorded, so it is always given back.
        batch->held.reserve(n);
        batch->heldBrains.reserve(n);
        // Every agent's in-use flag, and the flag of each body's brain, is held for the whole call,
        // as a single call holds them; an agent or brain listed twice is taken once (looked up
        // only when its flag is already held).
        struct Release {
            std::vector<verve_agent*>& held;
            std::vector<std::atomic<bool>*>& heldBrains;
            ~Release() {
                for (verve_agent* h : held) h->inUse.store(false, std::memory_order_release);
                for (std::atomic<bool>* b : heldBrains) b->store(false, std::memory_order_release);
                held.clear();
                heldBrains.clear();
            }
        } release{batch->held, batch->heldBrains};
        for (uint32_t i = 0; i < n; ++i) {
            verve_agent* h = agents[i];
            batch->agents[i] = nullptr;
            if (h == nullptr) continue;  // refused below, naming the agent
            if (verve::capi::tryAcquire(*h)) {
                batch->held.push_back(h);
            } else if (std::find(agents, agents + i, h) == agents + i) {
                verve::capi::refuseInUse();
            }
            if (std::atomic<bool>* brain = h->brainInUse.get()) {
                if (verve::capi::tryAcquire(*brain)) {
                    batch->heldBrains.push_back(brain);
                } else if (std::find(batch->heldBrains.begin(), batch->heldBrains.end(), brain) == batch->heldBrains.end()) {
                    verve::capi::refuseInUse();
                }
            }
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
        step.actions = out_actions;
        step.results = batch->results.data();
        try {
            batch->batch.update(step);
        } catch (...) {
            if (out_results != nullptr) {
                for (uint32_t i = 0; i < n; ++i) {
                    const int code = batch->results[i];
                    out_results[i] = code == 0 ? VERVE_OK : verve::capi::toResult(static_cast<verve::ErrorCode>(code));
                }
            }
            throw;
        }
        if (out_results != nullptr) {
            for (uint32_t i = 0; i < n; ++i) out_results[i] = VERVE_OK;
        }
    });
}

}  // extern "C"
