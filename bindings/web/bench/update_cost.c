/* The cost of one update on the cart-pole shape (4 continuous sensors, resolution 8, 3 actions,
 * the thesis's settings): the same C program built natively and to wasm (bindings/web/CMakeLists.txt),
 * so their ratio is the price of WebAssembly; update_cost.mjs does the same through the JS API.
 * A learning run with the physics in the loop (as bench/bench_shapes.hpp's CartPoleRun) records its
 * observation stream, then a fresh agent is timed on that stream alone, so neither the physics nor
 * the C library's sin/cos (glibc or musl) is in the time. `update_cost [updates]` prints:
 * <microseconds per update> <updates> <rbfs> */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <verve_c.h>

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

typedef struct { double x, v, theta, omega; } Cart;

static void physics(Cart* c, double force) {
    const double g = 9.81, poleMass = 0.1, halfLength = 0.5, total = 1.1;
    const double co = cos(c->theta), s = sin(c->theta);
    const double tmp = (force + poleMass * halfLength * c->omega * c->omega * s) / total;
    const double alpha = (g * s - co * tmp) / (halfLength * (4.0 / 3.0 - poleMass * co * co / total));
    const double a = tmp - poleMass * halfLength * alpha * co / total;
    c->x += 0.01 * c->v;
    c->v += 0.01 * a;
    c->theta += 0.01 * c->omega;
    c->omega += 0.01 * alpha;
}

static verve_agent* cartPoleAgent(void) {
    verve_agent_desc desc;
    verve_agent_desc_default(&desc);
    desc.num_continuous_sensors = 4;
    desc.resolution = 8;
    desc.num_actions = 3;
    desc.tau_value = 0.001f;
    desc.policy_multiplier = 50.0f;
    verve_agent* agent = NULL;
    verve_agent_create(&desc, &agent);
    return agent;
}

int main(int argc, char** argv) {
    const long updates = argc > 1 ? atol(argv[1]) : 200000;
    const long total = updates + updates / 4;  /* the first quarter warms up */
    float* obs = malloc(sizeof(float) * 4 * (size_t)total);
    float* rewards = malloc(sizeof(float) * (size_t)total);
    unsigned char* fell = malloc((size_t)total);
    verve_agent* agent = cartPoleAgent();
    if (!obs || !rewards || !fell || !agent) return 1;

    /* 1. A learning run with the physics in the loop, recorded: the observation stream of a real
     * cart-pole agent (trials that grow longer, ~1,250 RBFs). */
    const double limit = 12.0 * 3.14159265358979 / 180.0, spin = 100.0 * 3.14159265358979 / 180.0;
    Cart cart = {0, 0, 0, 0};
    uint32_t action = 2;
    int trial = 0;
    for (long i = 0; i < total; ++i) {
        const double force = action == 0 ? -10.0 : action == 1 ? 10.0 : 0.0;
        for (int k = 0; k < 5; ++k) physics(&cart, force);
        rewards[i] = 1.0f;
        fell[i] = fabs(cart.x) > 2.4 || fabs(cart.theta) > limit;
        if (fell[i]) {
            verve_agent_end_episode(agent, -1.0f);
            cart = (Cart){0, 0, 0.01 * ((trial++ % 7) - 3), 0};
            rewards[i] = 0.0f;
        }
        float* o = obs + 4 * i;
        o[0] = (float)(cart.x / 2.4);
        o[1] = (float)(cart.v / 2.4);
        o[2] = (float)(cart.theta / limit);
        o[3] = (float)(cart.omega / spin);
        if (verve_agent_update(agent, rewards[i], NULL, 0, o, 4, 0.05f, &action) != VERVE_OK) return 1;
    }
    verve_agent_destroy(agent);

    /* 2. A fresh agent given the same stream, timed: updates only, no physics. */
    agent = cartPoleAgent();
    double start = 0;
    for (long i = 0; i < total; ++i) {
        if (i == updates / 4) start = now();
        if (fell[i]) verve_agent_end_episode(agent, -1.0f);
        if (verve_agent_update(agent, rewards[i], NULL, 0, obs + 4 * i, 4, 0.05f, &action) != VERVE_OK) return 1;
    }
    const double seconds = now() - start;
    uint32_t rbfs = 0;
    verve_agent_get_rbf_count(agent, &rbfs);
    printf("%.3f %ld %u\n", seconds * 1e6 / (double)updates, updates, rbfs);
    verve_agent_destroy(agent);
    free(obs);
    free(rewards);
    free(fell);
    return 0;
}
