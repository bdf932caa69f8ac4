#include "capi/capi_in_use.hpp"

#include <algorithm>

#include "verve/error.hpp"

namespace verve::capi {

void refuseInUse() {
    throw Error(ErrorCode::InvalidState,
                "the agent is in use by another call right now (one agent is used by one thread at a time)");
}

void InUse::take(InUseFlag& flag, std::vector<InUseFlag*>* held) {
    if (!tryAcquire(flag)) {
        // Held already by this call, or by another: looked up only when the flag is taken.
        const bool ours = held != nullptr ? std::find(held->begin(), held->end(), &flag) != held->end()
                                          : std::find(inline_, inline_ + few_, &flag) != inline_ + few_;
        if (ours) return;
        refuseInUse();
    }
    if (held != nullptr) {
        held->push_back(&flag);  // within the reserved capacity: cannot throw
    } else if (few_ < 2) {
        inline_[few_++] = &flag;
    } else {
        release(flag);
        throw Error(ErrorCode::Internal, "InUse holds at most two flags without vectors");
    }
}

}  // namespace verve::capi
