#include "capi/capi_in_use.hpp"

#include <algorithm>

#include "verve/error.hpp"

namespace verve::capi {

void refuseInUse() {
    throw Error(ErrorCode::InvalidState,
                "the agent is in use by another call right now (one agent is used by one thread at a time)");
}

bool InUse::holds(const InUseFlag* flag) const noexcept {
    if (std::find(inline_, inline_ + few_, flag) != inline_ + few_) return true;
    return many_ != nullptr && std::find(many_->begin(), many_->end(), flag) != many_->end();
}

void InUse::take(InUseFlag& flag) {
    if (!tryAcquire(flag)) {
        if (holds(&flag)) return;  // looked up only when the flag is already taken
        refuseInUse();
    }
    if (many_ != nullptr) {
        many_->push_back(&flag);  // within the reserved capacity: cannot throw
    } else if (few_ < 2) {
        inline_[few_++] = &flag;
    } else {
        release(flag);
        throw Error(ErrorCode::Internal, "InUse holds at most two flags without a vector");
    }
}

}  // namespace verve::capi
