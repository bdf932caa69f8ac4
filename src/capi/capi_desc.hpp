// verve_agent_desc <-> verve::AgentDescriptor, honouring struct_size (older, smaller structs).
#pragma once
#include "verve/agent_descriptor.hpp"
#include "verve_c.h"

namespace verve::capi {

bool isKnownDescSize(std::uint32_t size) noexcept;
verve_agent_desc defaultDesc() noexcept;  // the full current struct
// Writes the defaults into the first `size` bytes (a known size). Throws Error(InvalidArgument).
void initDesc(verve_agent_desc& out, std::uint32_t size);
// Reads only desc.struct_size bytes; absent fields take defaults. Throws Error(InvalidArgument).
AgentDescriptor toDescriptor(const verve_agent_desc& desc);
// Writes only out.struct_size bytes (which must be a known size). Throws Error(InvalidArgument).
void writeDesc(const AgentDescriptor& descriptor, verve_agent_desc& out);

}  // namespace verve::capi
