// Every C++ allocation inside libverve (its own code and the C++ runtime linked into it) goes
// through the host's allocator hook. The version script keeps these replacements local to
// libverve: the host's own operator new and delete are untouched.
#include <cstddef>
#include <cstdint>
#include <new>

#include "capi/capi_memory.hpp"

using verve::capi::allocate;
using verve::capi::release;

namespace {

constexpr std::size_t kFundamental = alignof(std::max_align_t);

void* orThrow(void* block) {
    if (block == nullptr) throw std::bad_alloc();
    return block;
}

// Over-aligned types: over-allocate, and keep the block's start just before the aligned address.
void* allocateAligned(std::size_t size, std::align_val_t alignment) noexcept {
    const auto align = static_cast<std::size_t>(alignment);
    if (align <= kFundamental) return allocate(size);
    if (size > SIZE_MAX - align - sizeof(void*)) return nullptr;
    void* raw = allocate(size + align + sizeof(void*));
    if (raw == nullptr) return nullptr;
    const std::uintptr_t at = (reinterpret_cast<std::uintptr_t>(raw) + sizeof(void*) + align - 1) & ~(std::uintptr_t(align) - 1);
    reinterpret_cast<void**>(at)[-1] = raw;
    return reinterpret_cast<void*>(at);
}

void releaseAligned(void* block, std::align_val_t alignment) noexcept {
    if (block == nullptr) return;
    if (static_cast<std::size_t>(alignment) <= kFundamental) release(block);
    else release(static_cast<void**>(block)[-1]);
}

}  // namespace

void* operator new(std::size_t size) { return orThrow(allocate(size)); }
void* operator new[](std::size_t size) { return orThrow(allocate(size)); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void operator delete(void* block) noexcept { release(block); }
void operator delete[](void* block) noexcept { release(block); }
void operator delete(void* block, std::size_t) noexcept { release(block); }
void operator delete[](void* block, std::size_t) noexcept { release(block); }
void operator delete(void* block, const std::nothrow_t&) noexcept { release(block); }
void operator delete[](void* block, const std::nothrow_t&) noexcept { release(block); }

void* operator new(std::size_t size, std::align_val_t a) { return orThrow(allocateAligned(size, a)); }
void* operator new[](std::size_t size, std::align_val_t a) { return orThrow(allocateAligned(size, a)); }
void* operator new(std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept { return allocateAligned(size, a); }
void* operator new[](std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept { return allocateAligned(size, a); }
void operator delete(void* block, std::align_val_t a) noexcept { releaseAligned(block, a); }
void operator delete[](void* block, std::align_val_t a) noexcept { releaseAligned(block, a); }
void operator delete(void* block, std::size_t, std::align_val_t a) noexcept { releaseAligned(block, a); }
void operator delete[](void* block, std::size_t, std::align_val_t a) noexcept { releaseAligned(block, a); }
void operator delete(void* block, std::align_val_t a, const std::nothrow_t&) noexcept { releaseAligned(block, a); }
void operator delete[](void* block, std::align_val_t a, const std::nothrow_t&) noexcept { releaseAligned(block, a); }
