// What a user describes and what the library chooses. A task's descriptor holds both: the task's
// sensors and actions, and the settings its experiment was run with (the thesis's, for its tasks).
// The defaults table (scripts/defaults_table.sh) runs every task with everything but the
// description at the library's defaults.
#pragma once
#include <string>

#include "verve/agent_descriptor.hpp"

namespace verve::tasks {

// The task's sensors, actions, seed and feature choices (planning, curiosity), every learning
// setting at the library's default.
AgentDescriptor atLibraryDefaults(const AgentDescriptor& task);

// Applies one `key=value` setting by its C ABI name (tau_discount=2, resolution=16, planning=1, ...);
// throws std::invalid_argument for an unknown key or a value that is not a number.
void applySetting(AgentDescriptor& d, const std::string& setting);

}  // namespace verve::tasks
