/* verve_brain_methods.h - the methods of the VerveBrain class: one learner shared by many bodies,
 * each an ordinary VerveAgent (docs/crowds.md). */
#ifndef VERVE_BRAIN_METHODS_H
#define VERVE_BRAIN_METHODS_H

#include "gd_call.h"

typedef struct vg_brain {
    verve_brain* handle;            /* NULL before create()/load() and after close() */
    char last_error[VG_ERROR_SIZE]; /* "" after a call that succeeded */
} vg_brain;

/* Lets go of the brain a VerveBrain instance holds (its destructor); bodies keep it alive. */
void vg_brain_destroy(void* instance);

#define VG_DECLARE(name) \
    godot_variant vg_brain_##name(godot_object* object, void* method_data, void* user_data, int argc, \
                                  godot_variant** argv);
VG_DECLARE(create)
VG_DECLARE(load)
VG_DECLARE(load_bytes)
VG_DECLARE(save)
VG_DECLARE(save_binary)
VG_DECLARE(save_bytes)
VG_DECLARE(save_binary_bytes)
VG_DECLARE(create_body)
VG_DECLARE(get_rbf_count)
VG_DECLARE(has_brain)
VG_DECLARE(close)
VG_DECLARE(get_last_error)
#undef VG_DECLARE

#endif
