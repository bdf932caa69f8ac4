/* gd_api.h - the GDNative API tables Godot hands the library when it loads it, and the few
 * helpers over them that the binding needs (strings, variants, errors, paths). */
#ifndef VERVE_GD_API_H
#define VERVE_GD_API_H

#include <stddef.h>

#include <gdnative_api_struct.gen.h>

#if defined(_WIN32)
#  define VG_EXPORT __declspec(dllexport)
#else
#  define VG_EXPORT __attribute__((visibility("default")))
#endif

extern const godot_gdnative_core_api_struct* vg_core;
extern const godot_gdnative_ext_nativescript_api_struct* vg_ns;
extern const godot_gdnative_core_1_1_api_struct* vg_core11;            /* NULL before Godot 3.1 */
extern const godot_gdnative_ext_nativescript_1_1_api_struct* vg_ns11; /* NULL before NativeScript 1.1 */

/* Finds the NativeScript extension; 0 when the engine has none (nothing can be registered).
 * `library` is the GDNativeLibrary being loaded: new instances of our classes need it. */
int vg_api_init(const godot_gdnative_core_api_struct* core, godot_object* library);

/* A new instance of this library's class `class_name` (a Reference), as GDScript's
 * preload("....gdns").new() makes it; *instance is its instance data. Null (and *instance NULL)
 * when the engine could not make one. */
godot_variant vg_new_instance(const char* class_name, void** instance);

/* Prints an error the way GDScript's push_error does (the editor's debugger lists it too). */
void vg_print_error(const char* function, const char* message);

godot_string vg_string(const char* utf8);
godot_variant vg_variant_string(const char* utf8);
godot_variant vg_variant_nil(void);
godot_variant vg_variant_bool(int b);
godot_variant vg_variant_int(int64_t i);
godot_variant vg_variant_real(double r);

/* The variant's type name as GDScript spells it ("int", "PoolIntArray"...). */
const char* vg_type_name(const godot_variant* v);

/* A String variant as UTF-8 (destroy it with vg_core->godot_char_string_destroy); with `globalize`
 * res:// and user:// paths become file-system paths (ProjectSettings.globalize_path). */
godot_char_string vg_utf8(const godot_variant* v, int globalize);

/* dict[key] = value, destroying the value variant. */
void vg_dict_set(godot_dictionary* dict, const char* key, godot_variant value);

#endif
