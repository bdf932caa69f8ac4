/* The Windows build of the Godot plugin, loaded as Godot 3 loads a GDNative library
 * (OS_Windows::open_dynamic_library): the library's folder added with AddDllDirectory, then
 * LoadLibraryExW with LOAD_LIBRARY_SEARCH_DEFAULT_DIRS, so verve.dll must be found beside the
 * plugin; then the three entry points Godot calls. Run under Wine by the mingw-release tests
 * (a Unix path becomes Wine's Z: drive); no engine. */
#include <stdio.h>
#include <string.h>
#include <windows.h>

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: verve_godot_windows_load <libverve_godot.dll>\n");
        return 2;
    }
    wchar_t path[MAX_PATH], folder[MAX_PATH];
    char windowsPath[MAX_PATH];
    if (strlen(argv[1]) + 3 >= MAX_PATH) return 2;
    snprintf(windowsPath, sizeof windowsPath, "%s%s", argv[1][0] == '/' ? "Z:" : "", argv[1]);
    for (char* c = windowsPath; *c; ++c)
        if (*c == '/') *c = '\\';
    MultiByteToWideChar(CP_UTF8, 0, windowsPath, -1, path, MAX_PATH);
    wcscpy(folder, path);
    wchar_t* slash = wcsrchr(folder, L'\\');
    if (slash == NULL) return 2;
    *slash = 0;
    DLL_DIRECTORY_COOKIE cookie = AddDllDirectory(folder);
    HMODULE plugin = LoadLibraryExW(path, NULL, LOAD_LIBRARY_SEARCH_DEFAULT_DIRS);
    if (cookie) RemoveDllDirectory(cookie);
    if (plugin == NULL) {
        fprintf(stderr, "cannot load %s (error %lu)\n", windowsPath, (unsigned long)GetLastError());
        return 1;
    }
    const char* entries[] = {"godot_gdnative_init", "godot_gdnative_terminate", "godot_nativescript_init"};
    int failed = 0;
    for (int i = 0; i < 3; ++i) {
        if (GetProcAddress(plugin, entries[i]) == NULL) {
            fprintf(stderr, "%s does not export %s\n", windowsPath, entries[i]);
            failed = 1;
        }
    }
    if (GetModuleHandleA("verve.dll") == NULL) {
        fprintf(stderr, "%s loaded without verve.dll\n", windowsPath);
        failed = 1;
    }
    FreeLibrary(plugin);
    if (!failed) printf("verve godot plugin for Windows: loads with verve.dll from its folder; 3 GDNative entry points\n");
    return failed;
}
