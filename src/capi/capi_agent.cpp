#include "capi/capi_agent.hpp"

namespace verve::capi {

bool tryAcquire(std::atomic<bool>& flag) noexcept {
    // Acquire pairs with the release in ~AgentUse: a call on another thread sees everything the
    // previous call wrote, as the host's own hand-over between threads would give.
    return !flag.exchange(true, std::memory_order_acquire);
}

bool tryAcquire(const verve_agent& handle) noexcept { return tryAcquire(handle.inUse); }

void refuseInUse() {
    throw Error(ErrorCode::InvalidState,
                "the agent is in use by another call right now (one agent is used by one thread at a time)");
}

}  // namespace verve::capi
