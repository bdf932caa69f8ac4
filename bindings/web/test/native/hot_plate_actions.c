/* The native side of test/determinism.test.js, run by it through VERVE_NATIVE_PROGRAM (built by
 * scripts/test_web.sh against the native libverve.so):
 *   hot_plate_actions              every action of three fixed-seed runs, one line each: the 1D hot
 *                                  plate of test/hot_plate.js with a discrete and with a continuous
 *                                  sensor, and a cart-pole-shaped agent (4 continuous sensors,
 *                                  planning on) on a fixed sensor sequence
 *   hot_plate_actions save DIR     trains a continuous hot-plate agent, saves DIR/native.xml and .bin
 *   hot_plate_actions play FILE    loads a save and prints the greedy actions of 5 hot-plate trials */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <verve_c.h>

#define MODULUS 2147483647
#define SIZE 20

static verve_agent* hotPlateAgent(int continuous, uint64_t seed) {
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
    verve_agent* agent = NULL;
    if (verve_agent_create(&desc, &agent) != VERVE_OK) fprintf(stderr, "%s\n", verve_last_error());
    return agent;
}

/* Trials of test/hot_plate.js's task, start positions drawn from `seed`; prints each action when
 * `print` is set. */
static int runTrials(verve_agent* agent, int continuous, uint64_t seed, int trials, int print) {
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
            if (print) putchar('0' + (int)action);
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
    if (print) putchar('\n');
    return 0;
}

static int hotPlate(int continuous) {
    verve_agent* agent = hotPlateAgent(continuous, 1);
    const int rc = agent ? runTrials(agent, continuous, 1, 30, 1) : 1;
    verve_agent_destroy(agent);
    return rc;
}

/* Sensor k at step i: ((i * (13 + 7k)) mod 201) / 100 - 1, in float; the reward favours action 1. */
static int fourSensors(int steps) {
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

static int save(const char* dir) {
    verve_agent* agent = hotPlateAgent(1, 2);
    if (!agent) return 1;
    int rc = runTrials(agent, 1, 2, 10, 0);
    char path[4096];
    snprintf(path, sizeof path, "%s/native.xml", dir);
    if (!rc && verve_agent_save(agent, path) != VERVE_OK) rc = 1;
    snprintf(path, sizeof path, "%s/native.bin", dir);
    if (!rc && verve_agent_save_binary(agent, path) != VERVE_OK) rc = 1;
    if (rc) fprintf(stderr, "%s\n", verve_last_error());
    verve_agent_destroy(agent);
    return rc;
}

static int play(const char* file) {
    verve_agent* agent;
    if (verve_agent_load(file, &agent) != VERVE_OK) {
        fprintf(stderr, "%s\n", verve_last_error());
        return 1;
    }
    verve_agent_set_action_selection(agent, VERVE_ACTION_GREEDY);
    const int rc = runTrials(agent, 1, 9, 5, 1);
    verve_agent_destroy(agent);
    return rc;
}

int main(int argc, char** argv) {
    if (argc == 3 && strcmp(argv[1], "save") == 0) return save(argv[2]);
    if (argc == 3 && strcmp(argv[1], "play") == 0) return play(argv[2]);
    return hotPlate(0) || hotPlate(1) || fourSensors(2000);
}
