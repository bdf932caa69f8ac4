/* The cost of one update on the cart-pole shape (4 continuous sensors, resolution 8, 3 actions,
 * the thesis's settings) with the task's own physics in the loop, as bench/bench_shapes.hpp's
 * CartPoleRun: the same C program built natively and to wasm (bindings/web/CMakeLists.txt), so
 * their ratio is the price of WebAssembly. update_cost.mjs measures it through the JS API.
 * Prints: <microseconds per update> <updates> <rbfs> */
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

int main(int argc, char** argv) {
    const long updates = argc > 1 ? atol(argv[1]) : 200000;
    verve_agent_desc desc;
    verve_agent_desc_default(&desc);
    desc.num_continuous_sensors = 4;
    desc.resolution = 8;
    desc.num_actions = 3;
    desc.tau_value = 0.001f;
    desc.policy_multiplier = 50.0f;
    verve_agent* agent;
    if (verve_agent_create(&desc, &agent) != VERVE_OK) return 1;
    const double limit = 12.0 * 3.14159265358979 / 180.0, spin = 100.0 * 3.14159265358979 / 180.0;
    Cart cart = {0, 0, 0, 0};
    uint32_t action = 2;
    int trial = 0;
    double start = 0;
    for (long i = 0; i < updates + updates / 4; ++i) {
        if (i == updates / 4) start = now();  /* the first quarter warms up */
        const double force = action == 0 ? -10.0 : action == 1 ? 10.0 : 0.0;
        for (int k = 0; k < 5; ++k) physics(&cart, force);
        float reward = 1.0f;
        if (fabs(cart.x) > 2.4 || fabs(cart.theta) > limit) {
            verve_agent_end_episode(agent, -1.0f);
            cart = (Cart){0, 0, 0.01 * ((trial++ % 7) - 3), 0};
            reward = 0.0f;
        }
        const float obs[4] = {(float)(cart.x / 2.4), (float)(cart.v / 2.4), (float)(cart.theta / limit), (float)(cart.omega / spin)};
        if (verve_agent_update(agent, reward, NULL, 0, obs, 4, 0.05f, &action) != VERVE_OK) return 1;
    }
    const double seconds = now() - start;
    uint32_t rbfs = 0;
    verve_agent_get_rbf_count(agent, &rbfs);
    printf("%.3f %ld %u\n", seconds * 1e6 / (double)updates, updates, rbfs);
    verve_agent_destroy(agent);
    return 0;
}
