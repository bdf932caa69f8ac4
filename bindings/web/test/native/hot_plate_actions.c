/* The native side of test/determinism.test.js: the 1D hot plate of test/hot_plate.js through the
 * C ABI, printing every action of a fixed-seed run, one line per sensor kind, and a line for a
 * cart-pole-shaped agent (4 continuous sensors, planning on) on a fixed sensor sequence. Built and
 * run by scripts/test_web.sh against the native libverve.so. */
#include <stdint.h>
#include <stdio.h>

#include <verve_c.h>

#define MODULUS 2147483647
#define SIZE 20

static int run(int continuous, uint64_t seed, int trials) {
    verve_agent_desc desc;
    verve_agent_desc_default(&desc);
    desc.num_actions = 3;
    desc.policy_multiplier = 10.0f;
    desc.seed = seed;
    if (continuous) {
        desc.num_continuous_sensors = 1;
        desc.resolution = 10;
    } else {
        desc.num_discrete_sensors = 1;
        desc.discrete_sensor_values[0] = SIZE;
    }
    verve_agent* agent;
    if (verve_agent_create(&desc, &agent) != VERVE_OK) {
        fprintf(stderr, "%s\n", verve_last_error());
        return 1;
    }
    int64_t rng = (int64_t)(seed % (MODULUS - 1)) + 1;
    for (int t = 0; t < trials; ++t) {
        rng = (rng * 16807) % MODULUS;
        int position = 1 + (int)(rng % (SIZE - 2));
        float reward = 0.0f;
        for (int step = 1; step <= 1000; ++step) {
            int32_t d = position;
            float c = -1.0f + (float)(position * 2) / (float)(SIZE - 1);
            uint32_t action;
            if (verve_agent_update(agent, reward, &d, continuous ? 0 : 1, &c, continuous ? 1 : 0, 0.1f, &action) != VERVE_OK) {
                fprintf(stderr, "%s\n", verve_last_error());
                return 1;
            }
            putchar('0' + (int)action);
            position += (int)action - 1;
            if (position < 0) position = 0;
            if (position > SIZE - 1) position = SIZE - 1;
            if (position == 0 || position == SIZE - 1) {
                verve_agent_end_episode(agent, 1.0f);
                break;
            }
            reward = -1.0f;
            if (step == 1000) verve_agent_truncate_episode(agent, reward);
        }
    }
    putchar('\n');
    verve_agent_destroy(agent);
    return 0;
}

/* Sensor k at step i: ((i * (13 + 7k)) mod 201) / 100 - 1, in float; the reward favours action 1. */
static int runFourSensors(int steps) {
    verve_agent_desc desc;
    verve_agent_desc_default(&desc);
    desc.num_actions = 3;
    desc.num_continuous_sensors = 4;
    desc.continuous_sensor_circular[2] = 1;
    desc.planning = 1;
    desc.seed = 11;
    verve_agent* agent;
    if (verve_agent_create(&desc, &agent) != VERVE_OK) return 1;
    float reward = 0.0f;
    for (int i = 0; i < steps; ++i) {
        float c[4];
        for (int k = 0; k < 4; ++k) c[k] = (float)((i * (13 + 7 * k)) % 201) / 100.0f - 1.0f;
        uint32_t action;
        if (verve_agent_update(agent, reward, NULL, 0, c, 4, 0.02f, &action) != VERVE_OK) {
            fprintf(stderr, "%s\n", verve_last_error());
            return 1;
        }
        putchar('0' + (int)action);
        reward = action == 1 ? 0.5f : -0.25f;
    }
    putchar('\n');
    verve_agent_destroy(agent);
    return 0;
}

int main(void) {
    return run(0, 1, 30) || run(1, 1, 30) || runFourSensors(2000);
}
