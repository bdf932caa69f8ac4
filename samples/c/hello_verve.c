/* hello_verve.c - a complete Verve host in C: an agent learns to walk to the right end of a line. */
#include <stdio.h>

#include "verve_c.h"

/* Every call returns a verve_result; on failure verve_last_error() says why. */
#define TRY(call)                                                                        \
    if ((result = (call)) != VERVE_OK) {                                                 \
        fprintf(stderr, "%s: %s (%s)\n", #call, verve_last_error(), verve_result_name(result)); \
        goto done;                                                                       \
    }

int main(void) {
    verve_result result = VERVE_OK;
    verve_agent* agent = NULL;
    verve_agent_desc desc;
    int trial;

    verve_agent_desc_init(&desc, sizeof desc);  /* defaults; writes only this header's struct */
    desc.num_continuous_sensors = 1;  /* the position, in [-1, 1] */
    desc.num_actions = 2;             /* 0: step left, 1: step right */
    TRY(verve_agent_create(&desc, &agent));

    for (trial = 1; trial <= 60; ++trial) {
        int cell = 10, steps = 0;     /* cells 0..20; the goal is cell 20 */
        float reward = 0.0f;          /* what the previous action earned */
        while (cell < 20 && steps < 1000) {
            float position = (float)cell / 10.0f - 1.0f;
            uint32_t action;
            TRY(verve_agent_update(agent, reward, NULL, 0, &position, 1, 0.1f, &action));
            cell += action == 1 ? 1 : (cell > 0 ? -1 : 0);
            reward = -0.1f;           /* every step costs a little */
            ++steps;
        }
        if (cell == 20) {
            TRY(verve_agent_end_episode(agent, 1.0f));      /* the goal: the trial really ended */
        } else {
            TRY(verve_agent_truncate_episode(agent, reward)); /* out of time: the line goes on */
        }
        if (trial % 10 == 0) printf("trial %2d: %3d steps (best 10)\n", trial, steps);
    }
    TRY(verve_agent_save(agent, "hello_verve.xml"));  /* atomic: a crash keeps the old save */

done:
    verve_agent_destroy(agent);       /* NULL is fine */
    return result == VERVE_OK ? 0 : 1;
}
