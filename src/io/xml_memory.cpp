#include "io/xml_memory.hpp"

#include <pugixml.hpp>

#include <atomic>
#include <cstdlib>
#include <new>

namespace verve::io {
namespace {

std::atomic<XmlAllocate> allocateFn{nullptr};
std::atomic<XmlRelease> releaseFn{nullptr};
thread_local bool ranOutOfMemory = false;

void* xmlAllocate(std::size_t size) {
    void* block = allocateFn.load(std::memory_order_acquire)(size);
    if (block == nullptr) ranOutOfMemory = true;
    return block;
}

void xmlRelease(void* block) { releaseFn.load(std::memory_order_acquire)(block); }

}  // namespace

void routeXmlMemory(XmlAllocate allocate, XmlRelease release) noexcept {
    allocateFn.store(allocate, std::memory_order_release);
    releaseFn.store(release, std::memory_order_release);
    pugi::set_memory_management_functions(&xmlAllocate, &xmlRelease);
}

void throwIfXmlRanOutOfMemory() {
    if (!ranOutOfMemory) return;
    ranOutOfMemory = false;
    throw std::bad_alloc();
}

}  // namespace verve::io
