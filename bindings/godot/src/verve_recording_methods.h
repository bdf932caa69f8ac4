/* verve_recording_methods.h - the methods of the VerveRecording class: demonstrated steps and trial
 * ends kept in memory, saved to a file or bytes and replayed into a VerveAgent (docs/teaching.md,
 * "Recordings"). */
#ifndef VERVE_RECORDING_METHODS_H
#define VERVE_RECORDING_METHODS_H

#include "gd_call.h"

typedef struct vg_recording {
    verve_recording* handle;        /* NULL before create()/load() and after close() */
    char last_error[VG_ERROR_SIZE]; /* "" after a call that succeeded */
} vg_recording;

/* Frees the recording a VerveRecording instance holds (its destructor). */
void vg_recording_destroy(void* instance);

#define VG_DECLARE(name) \
    godot_variant vg_recording_##name(godot_object* object, void* method_data, void* user_data, int argc, \
                                      godot_variant** argv);
VG_DECLARE(create)
VG_DECLARE(add_step)
VG_DECLARE(add_step_continuous)
VG_DECLARE(add_end_episode)
VG_DECLARE(add_truncation)
VG_DECLARE(get_size)
VG_DECLARE(save)
VG_DECLARE(save_bytes)
VG_DECLARE(load)
VG_DECLARE(load_bytes)
VG_DECLARE(has_recording)
VG_DECLARE(close)
VG_DECLARE(get_last_error)
#undef VG_DECLARE

/* VerveAgent.replay(recording): lives here, beside the class it reads. */
godot_variant vg_replay(godot_object* object, void* method_data, void* user_data, int argc, godot_variant** argv);

#endif
