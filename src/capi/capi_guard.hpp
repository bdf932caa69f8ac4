// The C ABI's error discipline: every entry point runs its body through guarded(), which clears
// the thread's last error, and turns any exception into a verve_result plus a message. Nothing
// thrown ever crosses into the host.
#pragma once
#include <new>

#include "verve/error.hpp"
#include "verve_c.h"

namespace verve::capi {

void clearLastError() noexcept;
// Records "<function>: <message>" for verve_last_error() (truncated, never allocates) and returns code.
verve_result recordError(const char* function, verve_result code, const char* message) noexcept;
verve_result toResult(ErrorCode code) noexcept;

// Refuses a NULL pointer argument with a message naming it.
inline void requireArg(const void* pointer, const char* name) {
    if (pointer == nullptr) throw Error(ErrorCode::InvalidArgument, std::string(name) + " is NULL");
}

template <typename Body>
verve_result guarded(const char* function, Body&& body) noexcept {
    try {
        clearLastError();
        body();
        return VERVE_OK;
    } catch (const Error& e) {
        return recordError(function, toResult(e.code()), e.what());
    } catch (const std::bad_alloc&) {
        return recordError(function, VERVE_ERROR_OUT_OF_MEMORY, "out of memory");
    } catch (const std::exception& e) {
        return recordError(function, VERVE_ERROR_INTERNAL, e.what());
    } catch (...) {
        return recordError(function, VERVE_ERROR_INTERNAL, "unknown exception");
    }
}

}  // namespace verve::capi
