// The two-call buffer pattern of the *_save_memory calls.
#pragma once
#include <cstddef>
#include <cstring>
#include <string>

#include "verve/error.hpp"

namespace verve::capi {

// Puts bytes.size() into `size`; copies the bytes when `buffer` is given and holds them (the
// capacity is the size passed in), else throws Error(BufferTooSmall). A NULL buffer only asks.
inline void copyOut(const std::string& bytes, void* buffer, std::size_t& size) {
    const std::size_t capacity = size;
    size = bytes.size();
    if (buffer == nullptr) return;  // the size query
    if (capacity < bytes.size()) {
        throw Error(ErrorCode::BufferTooSmall,
                    "the buffer holds " + std::to_string(capacity) + " bytes, the save needs " + std::to_string(bytes.size()));
    }
    std::memcpy(buffer, bytes.data(), bytes.size());
}

}  // namespace verve::capi
