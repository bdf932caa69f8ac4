/* gd_options.h - agent options as a GDScript Dictionary <-> verve_agent_desc. The keys are the
 * C# AgentOptions property names in snake_case; any key left out keeps libverve's default. */
#ifndef VERVE_GD_OPTIONS_H
#define VERVE_GD_OPTIONS_H

#include "gd_call.h"

/* The Dictionary argument i (absent: all defaults) over verve_agent_desc_default; unknown keys
 * and wrong types are errors. Value ranges are the library's to check, in verve_agent_create. */
int vg_options_read(vg_call* c, int i, verve_agent_desc* d);

/* Every option of d, as vg_options_read takes them. */
godot_variant vg_options_variant(const verve_agent_desc* d);

#endif
