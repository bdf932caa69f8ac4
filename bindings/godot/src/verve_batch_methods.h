/* verve_batch_methods.h - the methods of the VerveBatch class: many VerveAgents stepped in one call
 * on libverve's own threads, exactly as one update each in array order would (docs/crowds.md). */
#ifndef VERVE_BATCH_METHODS_H
#define VERVE_BATCH_METHODS_H

#include "gd_call.h"

typedef struct vg_batch {
    verve_batch* handle;            /* NULL before create() and after close() */
    verve_agent** agents;           /* update()'s agent list, kept between frames: no allocation per frame */
    uint32_t capacity;              /* entries in agents */
    char last_error[VG_ERROR_SIZE]; /* "" after a call that succeeded */
} vg_batch;

/* Joins the batch's threads and frees its agent list (its destructor). */
void vg_batch_destroy(void* instance);

#define VG_DECLARE(name) \
    godot_variant vg_batch_##name(godot_object* object, void* method_data, void* user_data, int argc, \
                                  godot_variant** argv);
VG_DECLARE(create)
VG_DECLARE(update)
VG_DECLARE(get_worker_count)
VG_DECLARE(has_batch)
VG_DECLARE(close)
VG_DECLARE(get_last_error)
#undef VG_DECLARE

#endif
