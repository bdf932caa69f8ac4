/* verve_brain_methods.c - what each VerveBrain method does, as verve_agent_methods.c does for
 * VerveAgent: a failure prints a Godot error, returns false or null and changes nothing. */
#include "verve_brain_methods.h"

#include "gd_options.h"

#define VG_METHOD(name)                                                                                     \
    godot_variant vg_brain_##name(godot_object* object, void* method_data, void* user_data, int argc, \
                                  godot_variant** argv)
#define VG_UNUSED (void)object, (void)method_data

void vg_brain_destroy(void* instance) {
    verve_brain_destroy(((vg_brain*)instance)->handle);
}

static int vg_begin_brain(vg_call* c, void* user_data, const char* method, int argc, godot_variant** argv,
                          int min_args, int max_args) {
    vg_brain* self = user_data;
    return vg_begin_class(c, vg_brain_class, self ? self->last_error : NULL, method, argc, argv, min_args, max_args);
}

/* The brain, or 0 with an error when there is none. */
static int vg_brain_handle(vg_call* c, void* user_data, verve_brain** out) {
    *out = ((vg_brain*)user_data)->handle;
    if (*out) return 1;
    return vg_fail(c, "this VerveBrain has no brain: call create(), load() or load_bytes() first (or it was closed)");
}

/* Replaces the brain held by self with `fresh`; bodies made from the old one keep it alive. */
static void vg_adopt(vg_brain* self, verve_brain* fresh) {
    verve_brain_destroy(self->handle);
    self->handle = fresh;
}

VG_METHOD(create) {
    vg_call c;
    verve_agent_desc d;
    verve_brain* fresh = NULL;
    VG_UNUSED;
    if (!vg_begin_brain(&c, user_data, "create", argc, argv, 0, 1) || !vg_options_read(&c, 0, &d) ||
        !vg_check(&c, verve_brain_create(&d, &fresh)))
        return vg_variant_bool(0);
    vg_adopt(user_data, fresh);
    return vg_variant_bool(1);
}

/* The library's loads and saves in vg_with_path's and vg_with_bytes's form. */
static verve_result vg_load_file(const char* path, void* out) { return verve_brain_load(path, out); }
static verve_result vg_load_memory(const void* data, size_t size, void* out) {
    return verve_brain_load_memory(data, size, out);
}
static verve_result vg_save_xml_file(const char* path, void* brain) { return verve_brain_save(brain, path); }
static verve_result vg_save_binary_file(const char* path, void* brain) { return verve_brain_save_binary(brain, path); }

VG_METHOD(load) {
    vg_call c;
    verve_brain* fresh = NULL;
    int ok;
    VG_UNUSED;
    ok = vg_begin_brain(&c, user_data, "load", argc, argv, 1, 1) && vg_with_path(&c, 0, vg_load_file, &fresh);
    if (ok) vg_adopt(user_data, fresh);
    return vg_variant_bool(ok);
}

VG_METHOD(load_bytes) {
    vg_call c;
    verve_brain* fresh = NULL;
    int ok;
    VG_UNUSED;
    ok = vg_begin_brain(&c, user_data, "load_bytes", argc, argv, 1, 1) && vg_with_bytes(&c, 0, vg_load_memory, &fresh);
    if (ok) vg_adopt(user_data, fresh);
    return vg_variant_bool(ok);
}

/* save and save_binary. */
static godot_variant vg_save_file(void* user_data, const char* method, int argc, godot_variant** argv, vg_path_fn save) {
    vg_call c;
    verve_brain* b;
    return vg_variant_bool(vg_begin_brain(&c, user_data, method, argc, argv, 1, 1) &&
                           vg_brain_handle(&c, user_data, &b) && vg_with_path(&c, 0, save, b));
}

VG_METHOD(save) {
    VG_UNUSED;
    return vg_save_file(user_data, "save", argc, argv, vg_save_xml_file);
}

VG_METHOD(save_binary) {
    VG_UNUSED;
    return vg_save_file(user_data, "save_binary", argc, argv, vg_save_binary_file);
}

static verve_result vg_save_xml_memory(const void* brain, void* buffer, size_t* size) {
    return verve_brain_save_memory((const verve_brain*)brain, buffer, size);
}

static verve_result vg_save_binary_memory(const void* brain, void* buffer, size_t* size) {
    return verve_brain_save_memory_binary((const verve_brain*)brain, buffer, size);
}

/* save_bytes and save_binary_bytes. */
static godot_variant vg_save_bytes(void* user_data, const char* method, int argc, godot_variant** argv,
                                   vg_save_memory_fn save) {
    vg_call c;
    verve_brain* b;
    if (!vg_begin_brain(&c, user_data, method, argc, argv, 0, 0) || !vg_brain_handle(&c, user_data, &b))
        return vg_variant_nil();
    return vg_save_to_bytes(&c, save, b);
}

VG_METHOD(save_bytes) {
    VG_UNUSED;
    return vg_save_bytes(user_data, "save_bytes", argc, argv, vg_save_xml_memory);
}

VG_METHOD(save_binary_bytes) {
    VG_UNUSED;
    return vg_save_bytes(user_data, "save_binary_bytes", argc, argv, vg_save_binary_memory);
}

VG_METHOD(create_body) {
    vg_call c;
    verve_brain* b;
    verve_agent* body = NULL;
    vg_agent* instance;
    godot_variant out;
    VG_UNUSED;
    if (!vg_begin_brain(&c, user_data, "create_body", argc, argv, 0, 0) || !vg_brain_handle(&c, user_data, &b))
        return vg_variant_nil();
    /* The VerveAgent first: a body made and then dropped would still count as one of the brain's
     * bodies (its random stream), so a failure must not make one. */
    out = vg_new_instance(vg_agent_class, (void**)&instance);
    if (!instance) {
        vg_fail(&c, "the engine could not make a VerveAgent (is the library's NativeScript set up?)");
        return out;
    }
    if (!vg_check(&c, verve_brain_create_body(b, &body))) {
        vg_core->godot_variant_destroy(&out);
        return vg_variant_nil();
    }
    instance->handle = body;
    return out;
}

VG_METHOD(get_rbf_count) {
    vg_call c;
    verve_brain* b;
    uint32_t n = 0;
    VG_UNUSED;
    if (!vg_begin_brain(&c, user_data, "get_rbf_count", argc, argv, 0, 0) || !vg_brain_handle(&c, user_data, &b) ||
        !vg_check(&c, verve_brain_get_rbf_count(b, &n)))
        return vg_variant_nil();
    return vg_variant_int(n);
}

VG_METHOD(has_brain) {
    vg_call c;
    VG_UNUSED;
    return vg_variant_bool(vg_begin_brain(&c, user_data, "has_brain", argc, argv, 0, 0) &&
                           ((vg_brain*)user_data)->handle != NULL);
}

VG_METHOD(close) {
    vg_call c;
    VG_UNUSED;
    if (vg_begin_brain(&c, user_data, "close", argc, argv, 0, 0)) vg_adopt(user_data, NULL);
    return vg_variant_nil();
}

VG_METHOD(get_last_error) {
    VG_UNUSED, (void)argc, (void)argv;
    return vg_variant_string(user_data ? ((vg_brain*)user_data)->last_error : "");
}
