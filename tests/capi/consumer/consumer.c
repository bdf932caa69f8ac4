/* Uses an installed libverve through its C ABI: create, learn a little, save to memory, load. */
#include <stdio.h>
#include <stdlib.h>

#include "verve_c.h"

static int fail(const char* what) {
    fprintf(stderr, "consumer_c: %s failed: %s\n", what, verve_last_error());
    return 1;
}

int main(void) {
    verve_agent_desc desc;
    verve_agent* agent = NULL;
    verve_agent* copy = NULL;
    size_t size = 0;
    char* buffer;
    int i;
    verve_agent_desc_default(&desc);
    desc.num_continuous_sensors = 1;
    desc.num_actions = 2;
    if (verve_agent_create(&desc, &agent) != VERVE_OK) return fail("create");
    for (i = 0; i < 100; ++i) {
        float x = (float)(i % 20) / 10.0f - 1.0f;
        uint32_t action;
        if (verve_agent_update(agent, x > 0.5f ? 1.0f : 0.0f, NULL, 0, &x, 1, 0.1f, &action) != VERVE_OK) return fail("update");
    }
    if (verve_agent_save_memory(agent, NULL, &size) != VERVE_OK) return fail("save_memory (size)");
    buffer = (char*)malloc(size);
    if (buffer == NULL || verve_agent_save_memory(agent, buffer, &size) != VERVE_OK) return fail("save_memory");
    if (verve_agent_load_memory(buffer, size, &copy) != VERVE_OK) return fail("load_memory");
    free(buffer);
    verve_agent_destroy(copy);
    verve_agent_destroy(agent);
    printf("consumer_c: ok (version 0x%06x, save of %lu bytes)\n", (unsigned)verve_version(), (unsigned long)size);
    return 0;
}
