// pugixml's memory: routed through the library's allocator (the host's hooks), and its
// out-of-memory failures made visible (pugixml reports some only by returning empty nodes).
#pragma once
#include <cstddef>

namespace verve::io {

using XmlAllocate = void* (*)(std::size_t) noexcept;
using XmlRelease = void (*)(void*) noexcept;

void routeXmlMemory(XmlAllocate allocate, XmlRelease release) noexcept;

// Throws std::bad_alloc if pugixml failed an allocation on this thread since the last call.
void throwIfXmlRanOutOfMemory();

}  // namespace verve::io
