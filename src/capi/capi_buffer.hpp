// The two-call buffer pattern of the *_save_memory calls (agents and brains), serialised once for
// both calls.
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <utility>

#include "verve/error.hpp"
#include "verve/io.hpp"

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

// Counts the changes to what an agent or a brain would save, so that a kept save is served only
// while it is current. Shared by a brain and all its bodies, since each of their saves holds the
// shared weights. Only the holder of the in-use flag changes it (AgentUse), so relaxed order suffices.
using ChangeCounter = std::shared_ptr<std::atomic<std::uint64_t>>;
inline ChangeCounter newChangeCounter() { return std::make_shared<std::atomic<std::uint64_t>>(0); }

// A handle's save from its latest size query. The call with a buffer that follows copies these
// bytes instead of serialising again, if it asks for the same format and the counter has not moved
// (nothing changed in between); else it serialises afresh. Delivered bytes are freed at once; a
// size query without a second call holds them until the next memory save or the handle's end.
class KeptSave {
public:
    // copyOut of the save that serialise() makes (a std::string), run only when nothing current is kept.
    template <typename Serialise>
    void serve(SaveFormat format, const std::atomic<std::uint64_t>& changes, Serialise&& serialise, void* buffer,
               std::size_t& size) {
        const std::uint64_t now = changes.load(std::memory_order_relaxed);
        if (!kept_ || format_ != format || at_ != now) {
            bytes_ = std::forward<Serialise>(serialise)();
            kept_ = true;
            format_ = format;
            at_ = now;
        }
        copyOut(bytes_, buffer, size);
        if (buffer != nullptr) {  // delivered
            kept_ = false;
            std::string().swap(bytes_);
        }
    }

private:
    bool kept_ = false;
    std::string bytes_;
    SaveFormat format_ = SaveFormat::Xml;
    std::uint64_t at_ = 0;
};

}  // namespace verve::capi
