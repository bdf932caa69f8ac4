// Asking for memory before it is read: a crowd's update follows a chain of pointers (agent, brain,
// arrays, rows) whose every link misses the cache, so a batch asks for the next agents' links ahead
// of time (Agent::Impl::prefetch). A hint only: it never faults and changes no result.
#pragma once
#include <cstddef>

// Every function here is always inlined, at -O0 too: an out-of-line (weak) copy emitted in
// kernels_avx2.cpp would be AVX2 code the linker may pick for every caller, and a CPU without AVX2
// would then crash in portable code (tests/core/check_avx2_object.cmake, also at -O0).
#if defined(__GNUC__)
#define VERVE_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define VERVE_ALWAYS_INLINE inline
#endif

namespace verve::core {

constexpr std::size_t kCacheLine = 64;

// One cache line, to be read or to be written.
VERVE_ALWAYS_INLINE void prefetchLine(const void* p) noexcept { __builtin_prefetch(p, 0); }
VERVE_ALWAYS_INLINE void prefetchLineForWrite(const void* p) noexcept { __builtin_prefetch(p, 1); }
// Into the second-level cache only (PrefetchQueue): the first holds what is read now.
VERVE_ALWAYS_INLINE void prefetchLineToL2(const void* p) noexcept { __builtin_prefetch(p, 0, 2); }

// The cache lines of [p, p + bytes), at most maxLines of them (the first ones: the hardware
// prefetcher follows a stream once it has begun).
VERVE_ALWAYS_INLINE void prefetchBytes(const void* p, std::size_t bytes, std::size_t maxLines = 16) noexcept {
    const char* c = static_cast<const char*>(p);
    if (c == nullptr) return;
    const std::size_t lines = (bytes + kCacheLine - 1) / kCacheLine;
    for (std::size_t i = 0; i < lines && i < maxLines; ++i) prefetchLine(c + i * kCacheLine);
}

template <typename Vector>
VERVE_ALWAYS_INLINE void prefetchData(const Vector& v, std::size_t maxLines = 16) noexcept {
    prefetchBytes(v.data(), v.size() * sizeof(v[0]), maxLines);
}

// The next agent's arrays, asked for a few lines at a time from inside the loops of this agent's
// update (the kernels take it through ScanParams, TraceStep and rowSums), so that they arrive while
// this one computes. A crowd's update reads tens of kilobytes (a cart-pole-shaped agent: centres,
// weights and traces of 676 RBFs, ~450 cache lines); asked for all at once they gained nothing
// (docs/performance.md). Into the second-level cache: the first level holds this update's.
class PrefetchQueue {
public:
    VERVE_ALWAYS_INLINE void clear() noexcept { count_ = next_ = 0; bytes_ = 0; }
    // Ranges are asked for in the order they are added (up to kRanges of them).
    VERVE_ALWAYS_INLINE void add(const void* p, std::size_t bytes) noexcept {
        if (p == nullptr || bytes == 0 || count_ == kRanges) return;
        ranges_[count_++] = Range{static_cast<const char*>(p), static_cast<const char*>(p) + bytes};
        bytes_ += bytes;
    }
    VERVE_ALWAYS_INLINE std::size_t bytes() const noexcept { return bytes_; }
    // Asks for the next `lines` cache lines, if any are left.
    VERVE_ALWAYS_INLINE void askNext(unsigned lines) noexcept {
        for (; lines > 0 && next_ < count_; --lines) {
            Range& r = ranges_[next_];
            prefetchLineToL2(r.at);
            r.at += kCacheLine;
            if (r.at >= r.end) ++next_;
        }
    }

private:
    struct Range {
        const char* at;
        const char* end;
    };
    static constexpr unsigned kRanges = 7;  // up to four lattices, weights, live list, traces
    Range ranges_[kRanges];
    unsigned count_ = 0, next_ = 0;
    std::size_t bytes_ = 0;
};

// For a kernel's loop: `lines` more of the queue, when there is one.
VERVE_ALWAYS_INLINE void askAhead(PrefetchQueue* ahead, unsigned lines) noexcept {
    if (ahead != nullptr) ahead->askNext(lines);
}

}  // namespace verve::core
