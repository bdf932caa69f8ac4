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

// The flags one call holds, given back (in reverse) when it ends, however it ends. Up to two are
// kept inline (an agent and its brain: no allocation); a batch lends a vector it reuses (its
// capacity reserved before the first take, so a flag once taken is always recorded).
class InUse {
public:
    InUse() = default;
    explicit InUse(std::vector<InUseFlag*>& many) : many_(&many) { many.clear(); }
    ~InUse() {
        if (many_ != nullptr) {
            for (std::size_t i = many_->size(); i > 0; --i) release(*(*many_)[i - 1]);
            many_->clear();
        }
        for (std::size_t i = few_; i > 0; --i) release(*inline_[i - 1]);
    }
    InUse(const InUse&) = delete;
    InUse& operator=(const InUse&) = delete;

    // Takes `flag` for this call, or throws Error(InvalidState) when another call holds it. A flag
    // this call holds already (an agent listed twice, two bodies of one brain) is fine.
    void take(InUseFlag& flag);

private:
    bool holds(const InUseFlag* flag) const noexcept;

    InUseFlag* inline_[2] = {};
    std::size_t few_ = 0;
    std::vector<InUseFlag*>* many_ = nullptr;
};

}  // namespace verve::capi
