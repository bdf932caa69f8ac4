/* The Windows build of the Godot plugin, loaded and driven as Godot 3 drives a GDNative library,
 * under Wine (no Windows Godot is reachable here):
 * - loaded as OS_Windows::open_dynamic_library does: the library's folder added with
 *   AddDllDirectory, then LoadLibraryExW with LOAD_LIBRARY_SEARCH_DEFAULT_DIRS, so verve.dll must be
 *   found beside the plugin;
 * - its three entry points called as Godot calls them, with a stand-in for Godot's API (the few
 *   core calls the plugin makes, variants and strings in our own layout, NativeScript registration
 *   recorded): godot_gdnative_init, godot_nativescript_init (4 classes and their methods
 *   registered), then a VerveAgent made through its registered constructor and exercised through
 *   its registered methods (create, 400 updates of a two-armed bandit that it must learn, a reward
 *   outside [-1, 1] whose warning reaches Godot's print_warning through libverve's log hook, a
 *   refused dt that reaches print_error and get_last_error), destroyed, and
 *   godot_gdnative_terminate.
 * Run by the mingw-release tests (godot.windows_plugin_loads) and by package.sh on the bundle's copy
 * (a Unix path becomes Wine's Z: drive). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <windows.h>

#include <gdnative_api_struct.gen.h>

/* ---- a stand-in for Godot's API: what the plugin calls while it is driven below ------------- */
typedef struct {
    godot_variant_type type;
    union {
        godot_bool b;
        int64_t i;
        double r;
        char* s;
    } as;
} fake_variant;
typedef char fake_variant_fits[sizeof(fake_variant) <= sizeof(godot_variant) ? 1 : -1];

static fake_variant* fv(godot_variant* v) { return (fake_variant*)v; }
static const fake_variant* cfv(const godot_variant* v) { return (const fake_variant*)v; }
static char** fs(godot_string* s) { return (char**)s; }
static char* const* cfs(const godot_string* s) { return (char* const*)s; }

static char last_printed_error[1024], last_printed_warning[1024];
static int errors_printed, warnings_printed, loading_errors;

static void GDAPI fake_string_new(godot_string* s) { *fs(s) = _strdup(""); }
static godot_string GDAPI fake_string_chars_to_utf8(const char* utf8) {
    godot_string s;
    *fs(&s) = _strdup(utf8);
    return s;
}
static void GDAPI fake_string_destroy(godot_string* s) { free(*fs(s)); }
static void GDAPI fake_variant_new_nil(godot_variant* v) { fv(v)->type = GODOT_VARIANT_TYPE_NIL; }
static void GDAPI fake_variant_new_bool(godot_variant* v, const godot_bool b) {
    fv(v)->type = GODOT_VARIANT_TYPE_BOOL;
    fv(v)->as.b = b;
}
static void GDAPI fake_variant_new_int(godot_variant* v, const int64_t i) {
    fv(v)->type = GODOT_VARIANT_TYPE_INT;
    fv(v)->as.i = i;
}
static void GDAPI fake_variant_new_real(godot_variant* v, const double r) {
    fv(v)->type = GODOT_VARIANT_TYPE_REAL;
    fv(v)->as.r = r;
}
static void GDAPI fake_variant_new_string(godot_variant* v, const godot_string* s) {
    fv(v)->type = GODOT_VARIANT_TYPE_STRING;
    fv(v)->as.s = _strdup(*cfs(s));
}
static void GDAPI fake_variant_destroy(godot_variant* v) {
    if (fv(v)->type == GODOT_VARIANT_TYPE_STRING) free(fv(v)->as.s);
    fv(v)->type = GODOT_VARIANT_TYPE_NIL;
}
static godot_variant_type GDAPI fake_variant_get_type(const godot_variant* v) { return cfv(v)->type; }
static godot_bool GDAPI fake_variant_as_bool(const godot_variant* v) { return cfv(v)->as.b; }
static int64_t GDAPI fake_variant_as_int(const godot_variant* v) { return cfv(v)->as.i; }
static double GDAPI fake_variant_as_real(const godot_variant* v) { return cfv(v)->as.r; }
static void GDAPI fake_print_error(const char* description, const char* function, const char* file, int line) {
    (void)file, (void)line;
    snprintf(last_printed_error, sizeof last_printed_error, "%s: %s", function, description);
    ++errors_printed;
}
static void GDAPI fake_print_warning(const char* description, const char* function, const char* file, int line) {
    (void)function, (void)file, (void)line;
    snprintf(last_printed_warning, sizeof last_printed_warning, "%s", description);
    ++warnings_printed;
}
static void GDAPI fake_report_loading_error(const godot_object* library, const char* what) {
    (void)library;
    fprintf(stderr, "the plugin reported a loading error: %s\n", what);
    ++loading_errors;
}

/* NativeScript registration, recorded. */
#define MAX_METHODS 256
static struct {
    const char* class_name;
    const char* name;
    godot_instance_method method;
} methods[MAX_METHODS];
static int method_count, class_count;
static godot_instance_create_func agent_create;
static godot_instance_destroy_func agent_destroy;

static void GDAPI fake_register_class(void* handle, const char* name, const char* base,
                                      godot_instance_create_func create, godot_instance_destroy_func destroy) {
    (void)handle, (void)base;
    ++class_count;
    if (strcmp(name, "VerveAgent") == 0) {
        agent_create = create;
        agent_destroy = destroy;
    }
}
static void GDAPI fake_register_method(void* handle, const char* class_name, const char* name,
                                       godot_method_attributes attributes, godot_instance_method method) {
    (void)handle, (void)attributes;
    if (method_count == MAX_METHODS) return;
    methods[method_count].class_name = class_name;
    methods[method_count].name = name;
    methods[method_count].method = method;
    ++method_count;
}
static void GDAPI fake_register_property(void* handle, const char* name, const char* path,
                                         godot_property_attributes* attributes, godot_property_set_func set,
                                         godot_property_get_func get) {
    (void)handle, (void)name, (void)path, (void)attributes, (void)set, (void)get;
}

/* Calls VerveAgent.<name>(args...) on the instance, as Godot calls a NativeScript method. */
static godot_variant call(void* instance, const char* name, int argc, godot_variant* args) {
    godot_variant* argv[4];
    for (int i = 0; i < argc; ++i) argv[i] = &args[i];
    for (int m = 0; m < method_count; ++m)
        if (strcmp(methods[m].class_name, "VerveAgent") == 0 && strcmp(methods[m].name, name) == 0)
            return methods[m].method.method(NULL, methods[m].method.method_data, instance, argc, argv);
    fprintf(stderr, "VerveAgent.%s is not registered\n", name);
    exit(1);
}

static godot_variant real(double r) {
    godot_variant v;
    fake_variant_new_real(&v, r);
    return v;
}

/* VerveAgent.update(reward, null, null, dt): an agent without sensors. */
static int64_t update(void* instance, double reward, double dt) {
    godot_variant args[4];
    args[0] = real(reward);
    fake_variant_new_nil(&args[1]);
    fake_variant_new_nil(&args[2]);
    args[3] = real(dt);
    godot_variant out = call(instance, "update", 4, args);
    return fake_variant_get_type(&out) == GODOT_VARIANT_TYPE_INT ? fake_variant_as_int(&out) : -100;
}

static int check(int ok, const char* what) {
    if (!ok) fprintf(stderr, "FAILED: %s\n", what);
    return ok;
}

/* Drives the plugin's entry points; returns the number of failed checks. */
static int drive(HMODULE plugin) {
    void(GDAPI * gdnative_init)(godot_gdnative_init_options*) =
        (void(GDAPI*)(godot_gdnative_init_options*))(void*)GetProcAddress(plugin, "godot_gdnative_init");
    void(GDAPI * gdnative_terminate)(godot_gdnative_terminate_options*) =
        (void(GDAPI*)(godot_gdnative_terminate_options*))(void*)GetProcAddress(plugin, "godot_gdnative_terminate");
    void(GDAPI * nativescript_init)(void*) = (void(GDAPI*)(void*))(void*)GetProcAddress(plugin, "godot_nativescript_init");
    static godot_gdnative_core_api_struct core;
    static godot_gdnative_ext_nativescript_api_struct nativescript;
    static const godot_gdnative_api_struct* extensions[1];
    int failed = 0;

    nativescript.type = GDNATIVE_EXT_NATIVESCRIPT;
    nativescript.version.major = 1;
    nativescript.godot_nativescript_register_class = fake_register_class;
    nativescript.godot_nativescript_register_method = fake_register_method;
    nativescript.godot_nativescript_register_property = fake_register_property;
    extensions[0] = (const godot_gdnative_api_struct*)&nativescript;
    core.type = GDNATIVE_CORE;
    core.version.major = 1;
    core.num_extensions = 1;
    core.extensions = extensions;
    core.godot_string_new = fake_string_new;
    core.godot_string_chars_to_utf8 = fake_string_chars_to_utf8;
    core.godot_string_destroy = fake_string_destroy;
    core.godot_variant_new_nil = fake_variant_new_nil;
    core.godot_variant_new_bool = fake_variant_new_bool;
    core.godot_variant_new_int = fake_variant_new_int;
    core.godot_variant_new_real = fake_variant_new_real;
    core.godot_variant_new_string = fake_variant_new_string;
    core.godot_variant_destroy = fake_variant_destroy;
    core.godot_variant_get_type = fake_variant_get_type;
    core.godot_variant_as_bool = fake_variant_as_bool;
    core.godot_variant_as_int = fake_variant_as_int;
    core.godot_variant_as_real = fake_variant_as_real;
    core.godot_print_error = fake_print_error;
    core.godot_print_warning = fake_print_warning;

    godot_gdnative_init_options options;
    memset(&options, 0, sizeof options);
    options.api_struct = &core;
    options.gd_native_library = (godot_object*)&options; /* any non-null object */
    options.report_loading_error = fake_report_loading_error;
    gdnative_init(&options);
    failed += !check(loading_errors == 0, "godot_gdnative_init accepts the API");
    nativescript_init(&options);
    failed += !check(class_count == 4 && agent_create.create_func != NULL && method_count >= 40,
                     "godot_nativescript_init registers VerveAgent, VerveBrain, VerveBatch, VerveRecording and their methods");
    if (failed) return failed;

    void* agent = agent_create.create_func(NULL, agent_create.method_data);
    godot_variant created = call(agent, "create", 0, NULL);
    failed += !check(fake_variant_get_type(&created) == GODOT_VARIANT_TYPE_BOOL && fake_variant_as_bool(&created),
                     "VerveAgent.create() with libverve's defaults (2 actions, no sensors)");
    /* A two-armed bandit: action 1 pays 1, action 0 nothing; the reward arrives with the next update. */
    int64_t action = update(agent, 0.0, 0.1);
    int late_ones = 0, bad_actions = 0;
    for (int step = 1; step <= 400; ++step) {
        action = update(agent, action == 1 ? 1.0 : 0.0, 0.1);
        if (action != 0 && action != 1) ++bad_actions;
        if (step > 300 && action == 1) ++late_ones;
    }
    failed += !check(bad_actions == 0, "VerveAgent.update returns an action, 0 or 1");
    failed += !check(late_ones >= 75, "the agent learned the paying action (at least 75 of its last 100 choices)");
    printf("two-armed bandit: the paying action in %d of the last 100 of 400 updates\n", late_ones);

    update(agent, 5.0, 0.1);
    failed += !check(warnings_printed == 1 && strstr(last_printed_warning, "a reward of 5 was clamped") != NULL,
                     "a reward outside [-1, 1] reaches Godot's print_warning through libverve's log hook");
    failed += !check(update(agent, 0.0, 0.0) == -1 && errors_printed == 1 &&
                         strstr(last_printed_error, "dt must be a finite number > 0") != NULL,
                     "a refused dt returns -1 and reaches Godot's print_error");
    godot_variant error = call(agent, "get_last_error", 0, NULL);
    failed += !check(fake_variant_get_type(&error) == GODOT_VARIANT_TYPE_STRING &&
                         strstr(fv(&error)->as.s, "VerveAgent.update: verve_agent_update: dt must be") != NULL,
                     "VerveAgent.get_last_error() names the refusal");
    fake_variant_destroy(&error);
    agent_destroy.destroy_func(NULL, agent_destroy.method_data, agent);

    godot_gdnative_terminate_options terminate_options = {0};
    gdnative_terminate(&terminate_options);
    return failed;
}

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
    if (!failed) failed = drive(plugin) != 0;
    FreeLibrary(plugin);
    if (!failed)
        printf("verve godot plugin for Windows: loads with verve.dll from its folder; its 3 GDNative entry points "
               "driven: classes registered, a VerveAgent created, learning, warning and refusing through Godot's API\n");
    return failed;
}
