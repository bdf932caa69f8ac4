// Asking for memory before it is read: a crowd's update follows a chain of pointers (agent, brain,
// arrays, rows) whose every link misses the cache, so a batch asks for the next agents' links ahead
// of time (Agent::Impl::prefetch). A hint only: it never faults and changes no result.
#pragma once
#include <cstddef>

namespace verve::core {

constexpr std::size_t kCacheLine = 64;

// One cache line, to be read or to be written.
inline void prefetchLine(const void* p) noexcept { __builtin_prefetch(p, 0); }
inline void prefetchLineForWrite(const void* p) noexcept { __builtin_prefetch(p, 1); }

// The cache lines of [p, p + bytes), at most maxLines of them (the first ones: the hardware
// prefetcher follows a stream once it has begun).
inline void prefetchBytes(const void* p, std::size_t bytes, std::size_t maxLines = 16) noexcept {
    const char* c = static_cast<const char*>(p);
    if (c == nullptr) return;
    const std::size_t lines = (bytes + kCacheLine - 1) / kCacheLine;
    for (std::size_t i = 0; i < lines && i < maxLines; ++i) prefetchLine(c + i * kCacheLine);
}

template <typename Vector>
void prefetchData(const Vector& v, std::size_t maxLines = 16) noexcept {
    prefetchBytes(v.data(), v.size() * sizeof(v[0]), maxLines);
}

}  // namespace verve::core
