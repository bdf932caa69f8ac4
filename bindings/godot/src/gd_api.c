#include "gd_api.h"

#include <string.h>

const godot_gdnative_core_api_struct* vg_core = NULL;
const godot_gdnative_ext_nativescript_api_struct* vg_ns = NULL;
const godot_gdnative_ext_nativescript_1_1_api_struct* vg_ns11 = NULL;

int vg_api_init(const godot_gdnative_core_api_struct* core) {
    unsigned int i;
    vg_core = core;
    vg_ns = NULL;
    vg_ns11 = NULL;
    for (i = 0; i < core->num_extensions; ++i) {
        const godot_gdnative_api_struct* ext = core->extensions[i];
        if (ext->type != GDNATIVE_EXT_NATIVESCRIPT) continue;
        vg_ns = (const godot_gdnative_ext_nativescript_api_struct*)ext;
        /* Newer versions hang off `next`; 1.1 adds argument names and documentation. */
        for (ext = ext->next; ext; ext = ext->next)
            if (ext->version.major == 1 && ext->version.minor == 1)
                vg_ns11 = (const godot_gdnative_ext_nativescript_1_1_api_struct*)ext;
    }
    return vg_ns != NULL;
}

void vg_print_error(const char* function, const char* message) {
    vg_core->godot_print_error(message, function, "libverve_godot", 0);
}

godot_string vg_string(const char* utf8) {
    return vg_core->godot_string_chars_to_utf8(utf8);
}

godot_variant vg_variant_string(const char* utf8) {
    godot_variant v;
    godot_string s = vg_string(utf8);
    vg_core->godot_variant_new_string(&v, &s);
    vg_core->godot_string_destroy(&s);
    return v;
}

godot_variant vg_variant_nil(void) {
    godot_variant v;
    vg_core->godot_variant_new_nil(&v);
    return v;
}

godot_variant vg_variant_bool(int b) {
    godot_variant v;
    vg_core->godot_variant_new_bool(&v, b != 0);
    return v;
}

godot_variant vg_variant_int(int64_t i) {
    godot_variant v;
    vg_core->godot_variant_new_int(&v, i);
    return v;
}

godot_variant vg_variant_real(double r) {
    godot_variant v;
    vg_core->godot_variant_new_real(&v, r);
    return v;
}

const char* vg_type_name(const godot_variant* v) {
    static const char* const names[] = {
        "null", "bool", "int", "float", "String", "Vector2", "Rect2", "Vector3", "Transform2D", "Plane",
        "Quat", "AABB", "Basis", "Transform", "Color", "NodePath", "RID", "Object", "Dictionary", "Array",
        "PoolByteArray", "PoolIntArray", "PoolRealArray", "PoolStringArray", "PoolVector2Array",
        "PoolVector3Array", "PoolColorArray"};
    godot_variant_type t = vg_core->godot_variant_get_type(v);
    return (unsigned)t < sizeof names / sizeof names[0] ? names[t] : "unknown";
}

godot_char_string vg_utf8(const godot_variant* v, int globalize) {
    godot_string s = vg_core->godot_variant_as_string(v);
    godot_char_string out;
    if (globalize) {
        static godot_method_bind* globalize_path = NULL;
        godot_object* settings = vg_core->godot_global_get_singleton((char*)"ProjectSettings");
        if (!globalize_path) globalize_path = vg_core->godot_method_bind_get_method("ProjectSettings", "globalize_path");
        if (settings && globalize_path) {
            const void* args[1] = {&s};
            godot_string global;
            vg_core->godot_string_new(&global);
            vg_core->godot_method_bind_ptrcall(globalize_path, settings, args, &global);
            vg_core->godot_string_destroy(&s);
            s = global;
        }
    }
    out = vg_core->godot_string_utf8(&s);
    vg_core->godot_string_destroy(&s);
    return out;
}

void vg_dict_set(godot_dictionary* dict, const char* key, godot_variant value) {
    godot_variant k = vg_variant_string(key);
    vg_core->godot_dictionary_set(dict, &k, &value);
    vg_core->godot_variant_destroy(&k);
    vg_core->godot_variant_destroy(&value);
}
