// Errors thrown by the C++ API. The C ABI maps each code to a verve_result.
#pragma once
#include <stdexcept>
#include <string>

namespace verve {

enum class ErrorCode {
    InvalidArgument = 1,  // bad sizes, out-of-range values, NaN/inf, bad descriptor
    InvalidState = 2,     // the call does not fit the agent's state
    Io = 3,               // a file could not be opened, written or renamed
    Format = 4,           // a save is corrupt, truncated or inconsistent
    Version = 5,          // a save from a newer format version
    OutOfMemory = 6,
    BufferTooSmall = 7,
    Internal = 8,
};

class Error : public std::runtime_error {
public:
    Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
    ErrorCode code() const noexcept { return code_; }

private:
    ErrorCode code_;
};

}  // namespace verve
