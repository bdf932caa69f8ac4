#include "capi/capi_memory.hpp"
#include "capi/capi_guard.hpp"

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/warnings.hpp"
#include "io/xml_memory.hpp"
#include "verve/error.hpp"

namespace verve::capi {
namespace {

// Atomics: hooks are read on every allocation, from whichever threads call Verve.
std::atomic<verve_malloc_fn> mallocHook{nullptr};
std::atomic<verve_free_fn> freeHook{nullptr};
std::atomic<void*> allocUser{nullptr};
std::atomic<verve_log_fn> logHook{nullptr};
std::atomic<void*> logUser{nullptr};
// Blocks handed out and not yet freed: the allocator may change only while this is 0, so that
// no block is ever freed by a different allocator than the one that made it.
std::atomic<std::int64_t> liveBlocks{0};

void forwardWarning(const char* message) noexcept {
    if (verve_log_fn log = logHook.load(std::memory_order_acquire)) {
        log(logUser.load(std::memory_order_relaxed), VERVE_LOG_WARNING, message);
    }
}

// pugixml allocates through the same functions from the library's start on.
const bool xmlRouted = (io::routeXmlMemory(&allocate, &release), true);

}  // namespace

void* allocate(std::size_t size) noexcept {
    if (size == 0) size = 1;
    const verve_malloc_fn hook = mallocHook.load(std::memory_order_acquire);
    void* block = hook != nullptr ? hook(allocUser.load(std::memory_order_relaxed), size) : std::malloc(size);
    if (block != nullptr) liveBlocks.fetch_add(1, std::memory_order_relaxed);
    return block;
}

void release(void* block) noexcept {
    if (block == nullptr) return;
    liveBlocks.fetch_sub(1, std::memory_order_relaxed);
    const verve_free_fn hook = freeHook.load(std::memory_order_acquire);
    if (hook != nullptr) hook(allocUser.load(std::memory_order_relaxed), block);
    else std::free(block);
}

void installHooks(const verve_hooks* hooks) {
    (void)xmlRouted;
    verve_hooks h{};
    if (hooks != nullptr) {
        if (hooks->struct_size != VERVE_HOOKS_SIZE_V1) {
            throw Error(ErrorCode::InvalidArgument, "hooks->struct_size is " + std::to_string(hooks->struct_size) +
                                                        ", expected sizeof(verve_hooks) = " + std::to_string(VERVE_HOOKS_SIZE_V1));
        }
        if ((hooks->malloc_fn == nullptr) != (hooks->free_fn == nullptr)) {
            throw Error(ErrorCode::InvalidArgument, "hooks->malloc_fn and hooks->free_fn must be set together");
        }
        h = *hooks;
    }
#ifndef VERVE_ROUTES_CXX_MEMORY
    if (h.malloc_fn != nullptr) {
        throw Error(ErrorCode::InvalidState,
                    "this libverve links the C++ runtime dynamically (built with VERVE_SELF_CONTAINED=OFF), so not "
                    "all of its memory can go through an allocator hook; only the log hook is accepted");
    }
#endif
    const std::int64_t live = liveBlocks.load(std::memory_order_acquire);
    if (live != 0) {
        throw Error(ErrorCode::InvalidState, "Verve still holds " + std::to_string(live) +
                                                 " memory blocks: set hooks before the first agent or after destroying the last");
    }
    allocUser.store(h.alloc_user, std::memory_order_relaxed);
    freeHook.store(h.free_fn, std::memory_order_release);
    mallocHook.store(h.malloc_fn, std::memory_order_release);
    logUser.store(h.log_user, std::memory_order_relaxed);
    logHook.store(h.log_fn, std::memory_order_release);
    core::setWarningSink(&forwardWarning);
}

}  // namespace verve::capi

extern "C" {

VERVE_API verve_result VERVE_CALL verve_set_hooks(const verve_hooks* hooks) {
    return verve::capi::guarded(__func__, [&] { verve::capi::installHooks(hooks); });
}

}  // extern "C"
