/* How the plugin host loads a library at run time: dlopen/dlsym on POSIX (plugin_loader_posix.c),
 * LoadLibrary/GetProcAddress on Windows (plugin_loader_win32.c). */
#ifndef VERVE_TEST_PLUGIN_LOADER_H
#define VERVE_TEST_PLUGIN_LOADER_H

void* plugin_open(const char* path);                  /* NULL on failure, plugin_error() says why */
void* plugin_symbol(void* plugin, const char* name);  /* NULL when the library does not export it */
void plugin_close(void* plugin);
const char* plugin_error(void);

#endif
