// Library-wide calls: version, the thread-local last error, result names.
#include <cstdio>

#include "capi/capi_guard.hpp"

namespace verve::capi {
namespace {

// A fixed buffer: recording an error must not allocate (it also reports out-of-memory).
thread_local char lastError[1024] = "";

}  // namespace

void clearLastError() noexcept { lastError[0] = '\0'; }

verve_result recordError(const char* function, verve_result code, const char* message) noexcept {
    std::snprintf(lastError, sizeof lastError, "%s: %s", function, message);
    return code;
}

verve_result toResult(ErrorCode code) noexcept {
    switch (code) {
        case ErrorCode::InvalidArgument: return VERVE_ERROR_INVALID_ARGUMENT;
        case ErrorCode::InvalidState: return VERVE_ERROR_INVALID_STATE;
        case ErrorCode::Io: return VERVE_ERROR_IO;
        case ErrorCode::Format: return VERVE_ERROR_FORMAT;
        case ErrorCode::Version: return VERVE_ERROR_VERSION;
        case ErrorCode::OutOfMemory: return VERVE_ERROR_OUT_OF_MEMORY;
        case ErrorCode::BufferTooSmall: return VERVE_ERROR_BUFFER_TOO_SMALL;
        case ErrorCode::Internal: return VERVE_ERROR_INTERNAL;
    }
    return VERVE_ERROR_INTERNAL;
}

}  // namespace verve::capi

extern "C" {

VERVE_API uint32_t VERVE_CALL verve_version(void) { return VERVE_VERSION_NUMBER; }

VERVE_API const char* VERVE_CALL verve_last_error(void) { return verve::capi::lastError; }

VERVE_API const char* VERVE_CALL verve_result_name(verve_result result) {
    switch (result) {
        case VERVE_OK: return "VERVE_OK";
        case VERVE_ERROR_INVALID_ARGUMENT: return "VERVE_ERROR_INVALID_ARGUMENT";
        case VERVE_ERROR_INVALID_STATE: return "VERVE_ERROR_INVALID_STATE";
        case VERVE_ERROR_IO: return "VERVE_ERROR_IO";
        case VERVE_ERROR_FORMAT: return "VERVE_ERROR_FORMAT";
        case VERVE_ERROR_VERSION: return "VERVE_ERROR_VERSION";
        case VERVE_ERROR_OUT_OF_MEMORY: return "VERVE_ERROR_OUT_OF_MEMORY";
        case VERVE_ERROR_BUFFER_TOO_SMALL: return "VERVE_ERROR_BUFFER_TOO_SMALL";
        case VERVE_ERROR_INTERNAL: return "VERVE_ERROR_INTERNAL";
    }
    return "VERVE_UNKNOWN_RESULT";  // a value from a newer header, or garbage
}

}  // extern "C"
