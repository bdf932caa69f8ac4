// Many agents per frame through the C ABI (docs/performance.md, scripts/bench_crowd.sh): one
// verve_batch_update of 100 to 10,000 agents, tiny (2 continuous sensors, resolution 8, 2
// actions) or cart-pole-shaped (4 continuous, resolution 8, 3 actions, ~676 RBFs each); each shape
// also with one lattice (the fine lattice or the pairs beside cleared; 1,000 and 10,000 agents), as
// separate agents or as bodies of one shared brain, on 1 or 2 threads; and, as the baseline, the
// same agents updated one verve_agent_update call after another. 60 Hz x 10,000 agents = 600k/s.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "crowd_path.hpp"
#include "verve_c.h"

namespace {

void check(verve_result r) {
    if (r != VERVE_OK) throw std::runtime_error(verve_last_error());
}

struct Shape {
    const char* name;
    uint32_t sensors, actions, rbfs;  // rbfs: how many the warm agent has before it is copied
    // Adaptation bits cleared: one lattice, to show the cost of the fine one (1-2 sensors) or of
    // the pairs beside a lattice of 3-4 sensors.
    uint64_t cleared = 0;
};
const Shape kTiny{"tiny", 2, 2, 0};
const Shape kTinyOneLattice{"tiny_one_lattice", 2, 2, 0, VERVE_ADAPT_FINE_LATTICE};
const Shape kCartPole{"cart_pole", 4, 3, 676};
const Shape kCartPoleOneLattice{"cart_pole_one_lattice", 4, 3, 676, VERVE_ADAPT_PAIRS_BESIDE};

void frame(const Shape& s, uint64_t t, float* out) { verve::bench::crowdFrame(s.sensors, t, out); }

// One agent of the shape, grown along the path to its RBF count (the tiny one for 4,000 steps),
// saved: every agent of a crowd is a copy of it.
std::string warmAgentSave(const Shape& s) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_continuous_sensors = s.sensors;
    d.resolution = 8;
    d.num_actions = s.actions;
    d.adaptation &= ~s.cleared;
    verve_agent* a = nullptr;
    check(verve_agent_create(&d, &a));
    std::vector<float> obs(s.sensors);
    uint32_t action = 0, rbfs = 0;
    for (uint64_t t = 0; s.rbfs > 0 ? rbfs < s.rbfs : t < 4000; ++t) {
        frame(s, t, obs.data());
        check(verve_agent_update(a, action == 0 ? 0.1f : -0.1f, nullptr, 0, obs.data(), s.sensors, 1.0f / 60, &action));
        check(verve_agent_get_rbf_count(a, &rbfs));
    }
    size_t size = 0;
    check(verve_agent_save_memory(a, nullptr, &size));
    std::string xml(size, '\0');
    check(verve_agent_save_memory(a, &xml[0], &size));
    verve_agent_destroy(a);
    return xml;
}

// A crowd: n agents (copies of the warm one) or n bodies of one brain (loaded from it). Kept
// between the benchmark's runs of the same configuration: building 10,000 agents takes seconds.
struct Crowd {
    const Shape* shape = nullptr;
    uint32_t n = 0;
    bool shared = false;
    verve_brain* brain = nullptr;
    std::vector<verve_agent*> agents;
    uint64_t step = 0;

    Crowd(const Shape& s, uint32_t count, bool oneBrain) : shape(&s), n(count), shared(oneBrain) {
        const std::string xml = warmAgentSave(s);
        agents.resize(n);
        if (shared) check(verve_brain_load_memory(xml.data(), xml.size(), &brain));
        for (auto*& a : agents) {
            check(shared ? verve_brain_create_body(brain, &a) : verve_agent_load_memory(xml.data(), xml.size(), &a));
        }
    }
    ~Crowd() {
        for (auto* a : agents) verve_agent_destroy(a);
        verve_brain_destroy(brain);
    }
    // The next frame's packed input: agent i is 97 * i frames along the path.
    void inputs(std::vector<float>& rewards, std::vector<float>& sensors, const std::vector<uint32_t>& actions) {
        ++step;
        rewards.resize(n);
        sensors.resize(std::size_t(n) * shape->sensors);
        for (uint32_t i = 0; i < n; ++i) {
            frame(*shape, step + 97ull * i, sensors.data() + std::size_t(i) * shape->sensors);
            rewards[i] = actions[i] == 0 ? 0.1f : -0.1f;
        }
    }
};

Crowd& crowdFor(const Shape& s, uint32_t n, bool shared) {
    static std::unique_ptr<Crowd> cached;
    if (!cached || cached->shape != &s || cached->n != n || cached->shared != shared) {
        cached.reset();  // free the previous crowd first: 10,000 cart-pole agents take ~0.8 GB
        cached = std::make_unique<Crowd>(s, n, shared);
    }
    return *cached;
}

// threads 0: no batch, one verve_agent_update per agent on this thread.
void BM_Crowd(benchmark::State& state, const Shape& s, uint32_t n, bool shared, uint32_t threads) {
    Crowd& crowd = crowdFor(s, n, shared);
    verve_batch* batch = nullptr;
    if (threads > 0) {
        verve_batch_desc bd;
        check(verve_batch_desc_default(&bd));
        bd.worker_count = threads;
        check(verve_batch_create(&bd, &batch));
    }
    std::vector<float> rewards, sensors;
    std::vector<uint32_t> actions(n, 0);
    for (auto _ : state) {
        state.PauseTiming();
        crowd.inputs(rewards, sensors, actions);
        state.ResumeTiming();
        if (batch != nullptr) {
            check(verve_batch_update(batch, crowd.agents.data(), n, rewards.data(), nullptr, nullptr, 0, sensors.data(),
                                     nullptr, static_cast<uint32_t>(sensors.size()), 1.0f / 60, actions.data(), nullptr));
        } else {
            for (uint32_t i = 0; i < n; ++i) {
                check(verve_agent_update(crowd.agents[i], rewards[i], nullptr, 0, sensors.data() + std::size_t(i) * s.sensors,
                                         s.sensors, 1.0f / 60, &actions[i]));
            }
        }
    }
    verve_batch_destroy(batch);
    state.counters["updates_per_s"] = benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate);
    uint32_t rbfs = 0;
    check(verve_agent_get_rbf_count(crowd.agents[0], &rbfs));
    state.counters["rbfs"] = rbfs;
}

int registerAll() {
    for (const Shape* s : {&kTiny, &kTinyOneLattice, &kCartPole, &kCartPoleOneLattice}) {
        for (uint32_t n : {100u, 1000u, 3000u, 10000u}) {
            if (s->cleared != 0 && n != 1000u && n != 10000u) continue;  // one lattice's rows: two sizes
            for (bool shared : {false, true}) {
                for (uint32_t threads : {0u, 1u, 2u}) {
                    const std::string name = std::string("crowd/") + s->name + "/" + std::to_string(n) +
                                             (shared ? "/one_brain" : "/separate") +
                                             (threads == 0 ? "/loop" : "/batch_threads:" + std::to_string(threads));
                    benchmark::RegisterBenchmark(name.c_str(), BM_Crowd, *s, n, shared, threads)
                        ->UseRealTime()
                        ->Unit(benchmark::kMillisecond);
                }
            }
        }
    }
    return 0;
}
const int registered = registerAll();

}  // namespace
