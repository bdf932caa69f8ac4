/* plugin_loader.h with dlopen. */
#define _POSIX_C_SOURCE 200809L
#include <dlfcn.h>
#include <stddef.h>

#include "plugin_loader.h"

void* plugin_open(const char* path) { return dlopen(path, RTLD_NOW | RTLD_LOCAL); }
void* plugin_symbol(void* plugin, const char* name) { return dlsym(plugin, name); }
void plugin_close(void* plugin) { dlclose(plugin); }
const char* plugin_error(void) {
    const char* error = dlerror();
    return error != NULL ? error : "unknown dlopen error";
}
