// The in-use protocol of the C ABI, written once: every call takes the in-use flags of the handles
// it touches (an agent's, a brain's shared by its bodies, a batch's) for its duration; a second
// thread arriving while one is held is refused with VERVE_ERROR_INVALID_STATE, never let in
// (docs/c-api.md "Failure model"). AgentUse, BrainUse, the batch call and the destroy calls use it.
#pragma once
#include <atomic>
#include <cstddef>
#include <vector>

namespace verve::capi {

using InUseFlag = std::atomic<bool>;

// Takes a flag; false when another call holds it. Acquire pairs with release(): a call on another
// thread sees everything the previous call wrote, as the host's own hand-over would give.
inline bool tryAcquire(InUseFlag& flag) noexcept { return !flag.exchange(true, std::memory_order_acquire); }
inline void release(InUseFlag& flag) noexcept { flag.store(false, std::memory_order_release); }

// Throws Error(InvalidState): the handle is in use by another call right now.
[[noreturn]] void refuseInUse();

// The flags one call holds, given back when it ends, however it ends. Up to two are kept inline
// (an agent and its brain: no allocation). A batch lends two vectors it reuses, with capacity
// reserved before the first take (so a flag once taken is always recorded): one for its agents'
// flags, one for their brains', which many bodies share: a flag already held is looked up among
// its own kind only (a crowd's bodies find their brain's among the few brains, not the agents).
class InUse {
public:
    InUse() = default;
    InUse(std::vector<InUseFlag*>& own, std::vector<InUseFlag*>& shared) : own_(&own), shared_(&shared) {
        own.clear();
        shared.clear();
    }
    ~InUse() {
        for (std::vector<InUseFlag*>* held : {shared_, own_}) {
            if (held == nullptr) continue;
            for (InUseFlag* flag : *held) release(*flag);
            held->clear();
        }
        for (std::size_t i = few_; i > 0; --i) release(*inline_[i - 1]);
    }
    InUse(const InUse&) = delete;
    InUse& operator=(const InUse&) = delete;

    // Takes an agent's (or a batch's, a brain handle's) flag for this call, or throws
    // Error(InvalidState) when another call holds it; one this call holds already (an agent
    // listed twice) is fine.
    void take(InUseFlag& flag) { take(flag, own_); }
    // The same for a flag several handles of the call share (a brain's, held by its bodies).
    void takeShared(InUseFlag& flag) { take(flag, shared_); }

private:
    void take(InUseFlag& flag, std::vector<InUseFlag*>* held);

    InUseFlag* inline_[2] = {};
    std::size_t few_ = 0;
    std::vector<InUseFlag*>* own_ = nullptr;
    std::vector<InUseFlag*>* shared_ = nullptr;
};

}  // namespace verve::capi
