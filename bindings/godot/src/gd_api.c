#include "gd_api.h"

#include <string.h>

const godot_gdnative_core_api_struct* vg_core = NULL;
const godot_gdnative_ext_nativescript_api_struct* vg_ns = NULL;
const godot_gdnative_core_1_1_api_struct* vg_core11 = NULL;
const godot_gdnative_ext_nativescript_1_1_api_struct* vg_ns11 = NULL;
static godot_object* vg_library = NULL;

int vg_api_init(const godot_gdnative_core_api_struct* core, godot_object* library) {
    const godot_gdnative_api_struct* next;
    unsigned int i;
    vg_core = core;
    vg_core11 = NULL;
    vg_ns = NULL;
    vg_ns11 = NULL;
    vg_library = library;
    for (next = core->next; next; next = next->next)
        if (next->version.major == 1 && next->version.minor == 1)
            vg_core11 = (const godot_gdnative_core_1_1_api_struct*)next;
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

/* object.method(arg) through the engine's variant call (it converts the argument); 0 on failure. */
static int vg_call_method(const char* class_name, const char* method, godot_object* object, const godot_variant* arg) {
    godot_method_bind* bind = vg_core->godot_method_bind_get_method(class_name, method);
    const godot_variant* args[1];
    godot_variant_call_error error;
    godot_variant result;
    if (!bind) return 0;
    args[0] = arg;
    result = vg_core->godot_method_bind_call(bind, object, args, 1, &error);
    vg_core->godot_variant_destroy(&result);
    return error.error == GODOT_CALL_ERROR_CALL_OK;
}

/* As godot-cpp's T::_new(): a NativeScript naming the class in our library, set on a new Reference. */
godot_variant vg_new_instance(const char* class_name, void** instance) {
    godot_class_constructor new_script = vg_core->godot_get_class_constructor("NativeScript");
    godot_class_constructor new_reference = vg_core->godot_get_class_constructor("Reference");
    godot_variant script, library, name, out;
    godot_object* object;
    int ok;
    *instance = NULL;
    if (!new_script || !new_reference || !vg_library) return vg_variant_nil();
    /* Each object goes into a variant at once: the variants hold the references that free them. */
    vg_core->godot_variant_new_object(&script, new_script());
    vg_core->godot_variant_new_object(&library, vg_library);
    name = vg_variant_string(class_name);
    object = new_reference();
    vg_core->godot_variant_new_object(&out, object);
    ok = vg_call_method("NativeScript", "set_library", vg_core->godot_variant_as_object(&script), &library) &&
         vg_call_method("NativeScript", "set_class_name", vg_core->godot_variant_as_object(&script), &name) &&
         vg_call_method("Object", "set_script", object, &script);
    vg_core->godot_variant_destroy(&name);
    vg_core->godot_variant_destroy(&library);
    vg_core->godot_variant_destroy(&script);
    if (ok) *instance = vg_ns->godot_nativescript_get_userdata(object);
    if (*instance) return out;
    vg_core->godot_variant_destroy(&out);
    return vg_variant_nil();
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
