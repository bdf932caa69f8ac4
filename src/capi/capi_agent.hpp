// The opaque handle behind verve_agent*: a verve::Agent and the flag that detects two threads
// using it at once.
#pragma once
#include <atomic>
#include <utility>

#include "capi/capi_guard.hpp"
#include "verve/agent.hpp"

struct verve_agent {
    explicit verve_agent(verve::Agent&& a) : agent(std::move(a)) {}
    verve::Agent agent;
    // Set for the duration of every call on this agent. Mutable: read-only calls take it too,
    // because they share the agent's scratch memory (one atomic exchange per call).
    mutable std::atomic<bool> inUse{false};
};

namespace verve::capi {

// Takes the in-use flag of a handle, or throws Error(InvalidState) when another call holds it.
bool tryAcquire(const verve_agent& handle) noexcept;
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
    }
    ~AgentUse() { handle_->inUse.store(false, std::memory_order_release); }
    AgentUse(const AgentUse&) = delete;
    AgentUse& operator=(const AgentUse&) = delete;

    auto& agent() const { return handle_->agent; }

private:
    Handle* handle_;
};

// Hands a new agent to the host: *out is written only once everything has succeeded.
inline void handOut(Agent&& agent, verve_agent** out) { *out = new verve_agent(std::move(agent)); }

}  // namespace verve::capi
