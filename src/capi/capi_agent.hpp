// The opaque handle behind verve_agent*: a verve::Agent, the flag that detects two threads using
// it at once, and the save of the latest size query.
#pragma once
#include <atomic>
#include <memory>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>

#include "capi/capi_guard.hpp"
#include "verve/agent.hpp"
#include "verve/io.hpp"

namespace verve::capi {

// Counts the changes to an agent's learned state, so that a kept save is served only while it is
// current. Shared by a brain and all its bodies, since a body's save holds the shared weights.
// Only the holder of the in-use flag changes it (AgentUse), so relaxed order suffices.
using ChangeCounter = std::shared_ptr<std::atomic<std::uint64_t>>;
inline ChangeCounter newChangeCounter() { return std::make_shared<std::atomic<std::uint64_t>>(0); }

}  // namespace verve::capi

struct verve_agent {
    explicit verve_agent(verve::Agent&& a) : agent_(std::move(a)) {}
    ~verve_agent() { dropSave(); }
    verve_agent(const verve_agent&) = delete;
    verve_agent& operator=(const verve_agent&) = delete;

    const verve::Agent& agent() const { return agent_; }
    // Every change goes through here (agent_ is private): it makes the kept save stale.
    verve::Agent& mutableAgent() {
        changes_->fetch_add(1, std::memory_order_relaxed);
        return agent_;
    }
    // A brain's body counts its changes with the brain (and so with every other body).
    void shareChangesWith(verve::capi::ChangeCounter brainChanges) { changes_ = std::move(brainChanges); }

    // verve_agent_save_memory's (and _binary's) two calls: the size query keeps the bytes it made,
    // and the call with a buffer in the same format copies them instead of serialising again, if
    // the agent (or, for a body, its brain) did not change in between.
    const std::string& keepSave(std::string bytes, verve::SaveFormat format) const {
        hasSave_ = true;
        save_ = std::move(bytes);
        saveFormat_ = format;
        saveAt_ = changes_->load(std::memory_order_relaxed);
        return save_;
    }
    const std::string* keptSave(verve::SaveFormat format) const {
        return hasSave_ && saveFormat_ == format && saveAt_ == changes_->load(std::memory_order_relaxed) ? &save_ : nullptr;
    }
    void dropSave() const {
        hasSave_ = false;
        std::string().swap(save_);
    }

    // Set for the duration of every call on this agent. Mutable: read-only calls take it too,
    // because they share the agent's scratch memory (one atomic exchange per call).
    mutable std::atomic<bool> inUse{false};
    // A body's brain: the flag its brain and all the brain's bodies share, since they share weights
    // (one brain and its bodies count as one agent). Null for an agent of its own.
    std::shared_ptr<std::atomic<bool>> brainInUse;

private:
    verve::Agent agent_;
    verve::capi::ChangeCounter changes_ = verve::capi::newChangeCounter();
    // Mutable: a save is a const call (one agent is used by one thread at a time).
    mutable bool hasSave_ = false;
    mutable std::string save_;
    mutable verve::SaveFormat saveFormat_ = verve::SaveFormat::Xml;
    mutable std::uint64_t saveAt_ = 0;
};

namespace verve::capi {

// Takes the in-use flag of a handle, or throws Error(InvalidState) when another call holds it.
bool tryAcquire(const verve_agent& handle) noexcept;
bool tryAcquire(std::atomic<bool>& flag) noexcept;
[[noreturn]] void refuseInUse();

// One call's exclusive use of an agent: a second thread arriving while it lasts is refused with
// VERVE_ERROR_INVALID_STATE, never let in (docs/c-api.md "Failure model"). Handle is verve_agent or
// const verve_agent; agent() is const for the read-only calls.
template <typename Handle>
class AgentUse {
public:
    explicit AgentUse(Handle* handle) : handle_(handle) {
        requireArg(handle, "agent");
        if (!tryAcquire(*handle)) refuseInUse();
        if (handle->brainInUse != nullptr && !tryAcquire(*handle->brainInUse)) {
            handle->inUse.store(false, std::memory_order_release);
            refuseInUse();
        }
    }
    ~AgentUse() {
        if (handle_->brainInUse != nullptr) handle_->brainInUse->store(false, std::memory_order_release);
        handle_->inUse.store(false, std::memory_order_release);
    }
    AgentUse(const AgentUse&) = delete;
    AgentUse& operator=(const AgentUse&) = delete;

    // The agent, const for the read-only calls; a change goes through mutableAgent (save cache).
    auto& agent() const {
        if constexpr (std::is_const_v<Handle>) return handle_->agent();
        else return handle_->mutableAgent();
    }

private:
    Handle* handle_;
};

// Hands a new agent to the host: *out is written only once everything has succeeded.
inline void handOut(Agent&& agent, verve_agent** out) { *out = new verve_agent(std::move(agent)); }

}  // namespace verve::capi
