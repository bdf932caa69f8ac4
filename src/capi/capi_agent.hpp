// The opaque handle behind verve_agent*: a verve::Agent, the flag that detects two threads using
// it at once, and the save of the latest size query.
#pragma once
#include <atomic>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>

#include "capi/capi_buffer.hpp"
#include "capi/capi_guard.hpp"
#include "capi/capi_in_use.hpp"
#include "verve/agent.hpp"
#include "verve/io.hpp"

struct verve_agent {
    explicit verve_agent(verve::Agent&& a) : agent_(std::move(a)) {}
    verve_agent(const verve_agent&) = delete;
    verve_agent& operator=(const verve_agent&) = delete;

    const verve::Agent& agent() const { return agent_; }
    // Every change goes through here (agent_ is private): it makes the kept save stale.
    verve::Agent& mutableAgent() {
        changes_->fetch_add(1, std::memory_order_relaxed);
        return agent_;
    }
    // A brain's body counts its changes with the brain (and so with every other body).
    void shareChangesWith(verve::capi::ChangeCounter brainChanges) {
        brainChanges_ = std::move(brainChanges);
        changes_ = brainChanges_.get();
    }

    // verve_agent_save_memory's (and _binary's) two calls serialise once: the size query keeps its
    // bytes for the call with a buffer, unless the agent (or, for a body, its brain) changed between.
    template <typename Serialise>
    void saveToBuffer(verve::SaveFormat format, Serialise&& serialise, void* buffer, std::size_t& size) const {
        save_.serve(format, *changes_, std::forward<Serialise>(serialise), buffer, size);
    }

    // Set for the duration of every call on this agent. Mutable: read-only calls take it too,
    // because they share the agent's scratch memory (one atomic exchange per call).
    mutable verve::capi::InUseFlag inUse{false};
    // A body's brain: the flag its brain and all the brain's bodies share, since they share weights
    // (one brain and its bodies count as one agent). Null for an agent of its own.
    std::shared_ptr<verve::capi::InUseFlag> brainInUse;

private:
    verve::Agent agent_;
    // An agent of its own counts in the handle: a block of its own would be one more cache miss
    // per update of a crowd's agent. A body counts with its brain (shareChangesWith).
    std::atomic<std::uint64_t> ownChanges_{0};
    std::atomic<std::uint64_t>* changes_ = &ownChanges_;
    verve::capi::ChangeCounter brainChanges_;  // a body's: keeps its brain's counter alive
    // Mutable: a save is a const call (one agent is used by one thread at a time).
    mutable verve::capi::KeptSave save_;
};

namespace verve::capi {

// One call's exclusive use of an agent (and of its brain, for a body): capi_in_use.hpp. Handle is
// verve_agent or const verve_agent; agent() is const for the read-only calls.
template <typename Handle>
class AgentUse {
public:
    explicit AgentUse(Handle* handle) : handle_(handle) {
        requireArg(handle, "agent");
        use_.take(handle->inUse);
        if (handle->brainInUse != nullptr) use_.takeShared(*handle->brainInUse);
    }

    // The agent, const for the read-only calls; a change goes through mutableAgent (save cache).
    auto& agent() const {
        if constexpr (std::is_const_v<Handle>) return handle_->agent();
        else return handle_->mutableAgent();
    }

private:
    Handle* handle_;
    InUse use_;
};

// Hands a new agent to the host: *out is written only once everything has succeeded.
inline void handOut(Agent&& agent, verve_agent** out) { *out = new verve_agent(std::move(agent)); }

}  // namespace verve::capi
