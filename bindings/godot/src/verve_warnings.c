/* verve_warnings.c - see verve_warnings.h. */
#include "verve_warnings.h"

#include "warning_queue.h"

static void vg_echo(const char* message) {
    vg_core->godot_print_warning(message, "verve", "libverve", 0);
}

void vg_warnings_install(void) {
    vw_set_echo(vg_echo);
    vw_install();
}

static void vg_append(void* user, const char* message) {
    godot_string s = vg_string(message);
    vg_core->godot_pool_string_array_append((godot_pool_string_array*)user, &s);
    vg_core->godot_string_destroy(&s);
}

godot_variant vg_take_warnings(godot_object* object, void* method_data, void* user_data, int argc,
                               godot_variant** argv) {
    godot_pool_string_array list;
    godot_variant out;
    (void)object, (void)method_data, (void)user_data, (void)argc, (void)argv;
    vw_install(); /* in case libverve held memory at load time (then it refuses, again, harmlessly) */
    vg_core->godot_pool_string_array_new(&list);
    vw_take(vg_append, &list);
    vg_core->godot_variant_new_pool_string_array(&out, &list);
    vg_core->godot_pool_string_array_destroy(&list);
    return out;
}
