/* verve_warnings.h - libverve's log warnings in Godot: printed in the engine's output as they come
 * (push_warning's channel: the Output panel and the debugger's Errors tab), and kept for
 * VerveAgent.take_warnings() (bindings/shared/warning_queue.h). */
#ifndef VERVE_GODOT_WARNINGS_H
#define VERVE_GODOT_WARNINGS_H

#include "gd_api.h"

/* Installs libverve's log hook; godot_gdnative_init calls it, before any agent exists. */
void vg_warnings_install(void);

/* VerveAgent.take_warnings() -> PoolStringArray: the warnings since the previous call, oldest first. */
godot_variant vg_take_warnings(godot_object* object, void* method_data, void* user_data, int argc,
                               godot_variant** argv);

#endif
