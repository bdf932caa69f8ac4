/* A host in plain C99 that loads libverve the way an engine loads a plugin (dlopen/dlsym, or
 * LoadLibrary/GetProcAddress on Windows; no link-time dependency), creates agents, trains one on
 * the 1D hot plate until it clearly learns, saves it, and checks that the loaded copy acts exactly
 * like the original.
 *
 * usage: verve_plugin_host_test <libverve.so or verve.dll> <scratch file for the save> */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plugin_loader.h"
#include "verve_c.h"

/* ---- the plugin's entry points ---- */
static struct {
    const char* (*last_error)(void);
    void (*desc_default)(verve_agent_desc*);
    verve_result (*create)(const verve_agent_desc*, verve_agent**);
    void (*destroy)(verve_agent*);
    verve_result (*update)(verve_agent*, float, const int32_t*, uint32_t, const float*, uint32_t, float, uint32_t*);
    verve_result (*end_episode)(verve_agent*, float);
    verve_result (*save)(const verve_agent*, const char*);
    verve_result (*load)(const char*, verve_agent**);
} api;

static int failures = 0;
#define CHECK(cond)                                                               \
    do {                                                                          \
        if (!(cond)) {                                                            \
            fprintf(stderr, "%s:%d: CHECK(%s) failed\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                           \
        }                                                                         \
    } while (0)
#define CHECK_OK(call)                                                                          \
    do {                                                                                        \
        verve_result r_ = (call);                                                               \
        if (r_ != VERVE_OK) {                                                                   \
            fprintf(stderr, "%s:%d: %s -> %d: %s\n", __FILE__, __LINE__, #call, (int)r_, api.last_error()); \
            exit(1);                                                                            \
        }                                                                                       \
    } while (0)

static void* symbol(void* lib, const char* name) {
    void* p = plugin_symbol(lib, name);
    if (p == NULL) {
        fprintf(stderr, "missing symbol %s: %s\n", name, plugin_error());
        exit(1);
    }
    return p;
}
/* ISO C has no cast from void* to a function pointer; copying the bits is the portable idiom. */
#define BIND(field, name)                      \
    do {                                       \
        void* p_ = symbol(lib, name);          \
        memcpy(&api.field, &p_, sizeof p_);    \
    } while (0)

/* ---- the 1D hot plate (thesis chapter 5): 20 cells, the two end cells are safe ---- */
enum { CELLS = 20, LEFT = 0, RIGHT = 1 };

static uint32_t rng_state = 12345u;
static int random_start(void) { /* a cell off the edges: 1..18 */
    rng_state = rng_state * 1664525u + 1013904223u;
    return 1 + (int)((rng_state >> 16) % (CELLS - 2));
}

/* One trial; returns the steps taken to reach a safe edge (capped). */
static int run_trial(verve_agent* agent, int start) {
    int position = start;
    float reward = 0.0f;
    int steps;
    for (steps = 0; steps < 1000; ++steps) {
        const int32_t sensor = position;
        uint32_t action = 0;
        CHECK_OK(api.update(agent, reward, &sensor, 1, NULL, 0, 0.1f, &action));
        if (action == LEFT) --position;
        else if (action == RIGHT) ++position;
        if (position == 0 || position == CELLS - 1) {
            CHECK_OK(api.end_episode(agent, 1.0f));
            return steps + 1;
        }
        reward = -1.0f; /* the plate hurts */
    }
    CHECK_OK(api.end_episode(agent, -1.0f));
    return steps;
}

static double mean_steps(verve_agent* agent, int trials) {
    long total = 0;
    int i;
    for (i = 0; i < trials; ++i) total += run_trial(agent, random_start());
    return (double)total / trials;
}

int main(int argc, char** argv) {
    void* lib;
    verve_agent_desc desc;
    verve_agent* agents[3] = {NULL, NULL, NULL};
    verve_agent* loaded = NULL;
    double first, last;
    int i;
    if (argc != 3) {
        fprintf(stderr, "usage: %s <libverve.so> <save file>\n", argv[0]);
        return 2;
    }
    lib = plugin_open(argv[1]);
    if (lib == NULL) {
        fprintf(stderr, "cannot load %s: %s\n", argv[1], plugin_error());
        return 1;
    }
    BIND(last_error, "verve_last_error");
    BIND(desc_default, "verve_agent_desc_default");
    BIND(create, "verve_agent_create");
    BIND(destroy, "verve_agent_destroy");
    BIND(update, "verve_agent_update");
    BIND(end_episode, "verve_agent_end_episode");
    BIND(save, "verve_agent_save");
    BIND(load, "verve_agent_load");
    CHECK(plugin_symbol(lib, "_ZN5verve5AgentC1ERKNS_15AgentDescriptorE") == NULL); /* no C++ symbols leak */

    api.desc_default(&desc);
    desc.num_discrete_sensors = 1;
    desc.discrete_sensor_values[0] = CELLS;
    desc.num_actions = 3;
    desc.policy_multiplier = 10.0f; /* the thesis's setting for the hot plate */
    for (i = 0; i < 3; ++i) {
        desc.seed = (uint64_t)(i + 1);
        CHECK_OK(api.create(&desc, &agents[i]));
    }

    first = mean_steps(agents[0], 10);
    for (i = 0; i < 120; ++i) run_trial(agents[0], random_start());
    last = mean_steps(agents[0], 20);
    printf("1D hot plate: mean steps %.1f over the first 10 trials, %.1f over trials 131-150 (optimum 5.0)\n",
           first, last);
    CHECK(last < 8.0);
    CHECK(last < 0.5 * first);

    /* Save, load, and both must act alike from the same state (learning on in both). */
    CHECK_OK(api.save(agents[0], argv[2]));
    CHECK_OK(api.load(argv[2], &loaded));
    for (i = 0; i < 200; ++i) {
        const int32_t sensor = (i * 7) % CELLS;
        uint32_t a = 9, b = 8;
        CHECK_OK(api.update(agents[0], -1.0f, &sensor, 1, NULL, 0, 0.1f, &a));
        CHECK_OK(api.update(loaded, -1.0f, &sensor, 1, NULL, 0, 0.1f, &b));
        CHECK(a == b);
    }
    {   /* Bad input through the plugin: an error code and a message, no crash. */
        const int32_t off_plate = CELLS;
        uint32_t a = 0;
        CHECK(api.update(loaded, 0.0f, &off_plate, 1, NULL, 0, 0.1f, &a) == VERVE_ERROR_INVALID_ARGUMENT);
        CHECK(strlen(api.last_error()) > 0);
        CHECK(api.update(NULL, 0.0f, NULL, 0, NULL, 0, 0.1f, NULL) == VERVE_ERROR_INVALID_ARGUMENT);
    }

    api.destroy(loaded);
    for (i = 0; i < 3; ++i) api.destroy(agents[i]);
    remove(argv[2]);
    plugin_close(lib);
    if (failures > 0) {
        fprintf(stderr, "%d check(s) failed\n", failures);
        return 1;
    }
    printf("plugin host: all checks passed\n");
    return 0;
}
