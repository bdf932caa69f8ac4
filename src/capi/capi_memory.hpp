// All of libverve's memory and warnings, routed through the host's hooks (verve_set_hooks).
#pragma once
#include <cstddef>

#include "verve_c.h"

namespace verve::capi {

// The host's malloc hook, or the C library's; NULL when out of memory. Never throws.
void* allocate(std::size_t size) noexcept;
void release(void* block) noexcept;

// Validates and installs hooks (NULL: defaults). Throws Error(InvalidArgument / InvalidState).
void installHooks(const verve_hooks* hooks);

}  // namespace verve::capi
