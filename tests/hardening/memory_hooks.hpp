// A counting allocator hook that can fail the N-th allocation, for the memory suites.
#pragma once
#include <atomic>
#include <cstdlib>
#include <string>

#include "verve_c.h"

namespace verve::hardening {

struct CountingAllocator {
    std::atomic<long> allocations{0};
    std::atomic<long> frees{0};
    std::atomic<long> failAt{-1};  // the allocation number that returns NULL (-1: none)

    static void* VERVE_CALL allocate(void* user, size_t size) {
        auto* self = static_cast<CountingAllocator*>(user);
        const long n = ++self->allocations;
        if (n == self->failAt.load()) return nullptr;
        return std::malloc(size);
    }
    static void VERVE_CALL release(void* user, void* block) {
        ++static_cast<CountingAllocator*>(user)->frees;
        std::free(block);
    }

    verve_hooks hooks(verve_log_fn log = nullptr, void* logUser = nullptr) {
        verve_hooks h{};
        h.struct_size = VERVE_HOOKS_SIZE_V1;
        h.malloc_fn = &allocate;
        h.free_fn = &release;
        h.alloc_user = this;
        h.log_fn = log;
        h.log_user = logUser;
        return h;
    }
};

// What save() returns, made with allocation failures off and not counted: a reference save taken
// between the calls of a sweep leaves the N-th allocation where it was.
template <typename Save>
std::string uncounted(CountingAllocator& allocator, Save&& save) {
    const long failAt = allocator.failAt.exchange(-1);
    const long count = allocator.allocations.load();
    std::string bytes = save();
    allocator.allocations = count;
    allocator.failAt = failAt;
    return bytes;
}

}  // namespace verve::hardening
