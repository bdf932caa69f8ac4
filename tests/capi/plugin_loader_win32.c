/* plugin_loader.h with LoadLibrary: how a Windows engine loads a native plugin. */
#include <stdio.h>
#include <string.h>
#include <windows.h>

#include "plugin_loader.h"

static char error_text[64];

static void* remember_error(void) {
    snprintf(error_text, sizeof error_text, "Windows error %lu", (unsigned long)GetLastError());
    return NULL;
}

void* plugin_open(const char* path) {
    HMODULE module = LoadLibraryA(path);
    return module != NULL ? (void*)module : remember_error();
}

void* plugin_symbol(void* plugin, const char* name) {
    /* ISO C has no cast between function and object pointers: copy the bits. */
    FARPROC function = GetProcAddress((HMODULE)plugin, name);
    void* pointer;
    if (function == NULL) return remember_error();
    memcpy(&pointer, &function, sizeof pointer);
    return pointer;
}

void plugin_close(void* plugin) { FreeLibrary((HMODULE)plugin); }
const char* plugin_error(void) { return error_text; }
