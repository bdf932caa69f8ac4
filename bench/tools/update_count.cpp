// Runs a fixed number of updates after a warm-up, for instruction counts that a loaded machine
// cannot blur (docs/performance.md):
//   valgrind --tool=callgrind --toggle-collect='*measuredUpdates*' build/bench/verve_update_count cart-pole
// Shapes: cart-pole (20,000 warm-up steps, 3,000 counted), dense-4d-R and dense-2d-R (the full
// lattice at resolution R; 500 warm-up, 300 counted), and crowds that do not fit in a 4 MB cache
// (crowd-cart-pole: 300 agents, crowd-tiny: 3,000; the shapes and path of verve_crowd_bench; 10
// frames of warm-up, 20 counted), for the cache simulation's misses per update:
//   valgrind --tool=callgrind --cache-sim=yes --LL=4194304,16,64 --toggle-collect='*measuredFrames*' \
//     build/bench/verve_update_count crowd-cart-pole
// brain-cart-pole: the same crowd as 1,000 bodies of one brain, each frame one batch call on one
// thread (the parallel phases of core/shared_step.cpp), counted the same way; brain-tiny: 3,000
// tiny bodies of one brain.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "bench_shapes.hpp"
#include "crowd_path.hpp"
#include "verve/batch.hpp"
#include "verve/brain.hpp"

namespace {

// Not inlined, so that callgrind can count exactly its calls.
template <typename Run>
__attribute__((noinline)) void measuredUpdates(Run& run, int count) {
    for (int i = 0; i < count; ++i) run.step();
}

template <typename Run>
void warmAndMeasure(Run& run, int warm, int count) {
    for (int i = 0; i < warm; ++i) run.step();
    measuredUpdates(run, count);
}

// A crowd: copies of one agent grown along the path, agent i reading it 97 * i frames along.
struct Crowd {
    Crowd(std::uint32_t sensors, std::uint32_t actions, std::uint32_t rbfs, std::uint32_t n) : sensors_(sensors) {
        verve::AgentDescriptor d;
        for (std::uint32_t k = 0; k < sensors; ++k) d.addContinuousSensor();
        d.resolution = 8;
        d.numActions = actions;
        verve::Agent warm(d);
        verve::Observation obs(d);
        std::uint32_t action = 0;
        for (std::uint64_t t = 0; rbfs > 0 ? warm.rbfCount() < rbfs : t < 4000; ++t) {  // as verve_crowd_bench
            verve::bench::crowdFrame(sensors, t, obs.continuous.data());
            action = warm.update(action == 0 ? 0.1f : -0.1f, obs, 1.0f / 60);
        }
        const verve::AgentSnapshot snapshot = warm.snapshot();
        for (std::uint32_t i = 0; i < n; ++i) agents_.push_back(std::make_unique<verve::Agent>(snapshot));
        actions_.assign(n, 0);
        obs_ = verve::Observation(d);
    }
    // One brain for n bodies, stepped through a batch of one thread.
    void shareOneBrain(std::uint32_t n) {
        brain_ = std::make_unique<verve::Brain>(agents_.front()->snapshot());
        agents_.clear();
        for (std::uint32_t i = 0; i < n; ++i) agents_.push_back(std::make_unique<verve::Agent>(brain_->makeBody()));
        actions_.assign(n, 0);
        verve::BatchOptions options;
        options.workerCount = 1;
        batch_ = std::make_unique<verve::Batch>(options);
    }
    void frame() {
        ++step_;
        if (batch_) {
            rewards_.resize(agents_.size());
            inputs_.resize(agents_.size() * sensors_);
            pointers_.clear();
            for (std::size_t i = 0; i < agents_.size(); ++i) {
                verve::bench::crowdFrame(sensors_, step_ + 97 * i, inputs_.data() + i * sensors_);
                rewards_[i] = actions_[i] == 0 ? 0.1f : -0.1f;
                pointers_.push_back(agents_[i].get());
            }
            verve::BatchStep s;
            s.agents = pointers_.data();
            s.count = pointers_.size();
            s.rewards = rewards_.data();
            s.continuous = inputs_.data();
            s.continuousTotal = inputs_.size();
            s.dt = 1.0f / 60;
            s.actions = actions_.data();
            batch_->update(s);
            return;
        }
        for (std::size_t i = 0; i < agents_.size(); ++i) {
            verve::bench::crowdFrame(sensors_, step_ + 97 * i, obs_.continuous.data());
            actions_[i] = agents_[i]->update(actions_[i] == 0 ? 0.1f : -0.1f, obs_, 1.0f / 60);
        }
    }
    std::uint32_t sensors_;
    std::uint64_t step_ = 0;
    std::vector<std::unique_ptr<verve::Agent>> agents_;
    std::vector<std::uint32_t> actions_;
    verve::Observation obs_;
    std::unique_ptr<verve::Brain> brain_;  // brain-cart-pole: the bodies' brain and their batch
    std::unique_ptr<verve::Batch> batch_;
    std::vector<verve::Agent*> pointers_;
    std::vector<float> rewards_, inputs_;
};

// Not inlined, so that callgrind collects exactly these frames.
__attribute__((noinline)) void measuredFrames(Crowd& crowd, int count) {
    for (int i = 0; i < count; ++i) crowd.frame();
}

}  // namespace

int main(int argc, char** argv) {
    const std::string shape = argc > 1 ? argv[1] : "";
    if (shape == "crowd-cart-pole" || shape == "crowd-tiny" || shape == "brain-cart-pole" || shape == "brain-tiny") {
        const bool tiny = shape == "crowd-tiny" || shape == "brain-tiny";
        const bool brain = shape == "brain-cart-pole" || shape == "brain-tiny";
        Crowd crowd(tiny ? 2 : 4, tiny ? 2 : 3, tiny ? 0 : 676, brain ? 1 : tiny ? 3000 : 300);
        if (brain) crowd.shareOneBrain(tiny ? 3000 : 1000);
        for (int i = 0; i < 10; ++i) crowd.frame();
        measuredFrames(crowd, 20);
        std::printf("%s: %zu agents x 20 frames = %zu updates counted\n", shape.c_str(), crowd.agents_.size(),
                    crowd.agents_.size() * 20);
        return 0;
    }
    if (shape == "cart-pole") {
        verve::Agent agent(verve::bench::cartPoleAgent());
        verve::bench::CartPoleRun run(agent);
        warmAndMeasure(run, 20000, 3000);
        std::printf("cart-pole: 3000 updates counted at %zu RBFs\n", agent.rbfCount());
        return 0;
    }
    int dims = 0;
    unsigned resolution = 0;
    if (std::sscanf(shape.c_str(), "dense-%dd-%u", &dims, &resolution) == 2 && (dims == 2 || dims == 4) &&
        resolution >= 1 && resolution <= (dims == 2 ? 400u : 40u)) {
        const auto d = verve::bench::denseAgent(dims, resolution);
        verve::Agent agent(d);
        verve::bench::PathRun run(agent, d);
        warmAndMeasure(run, 500, 300);
        std::printf("%s: 300 updates counted at %zu RBFs\n", shape.c_str(), agent.rbfCount());
        return 0;
    }
    std::fprintf(stderr, "usage: verve_update_count cart-pole | dense-4d-R | dense-2d-R (R: resolution, at most 40 in 4-D, 400 in "
                         "2-D) | crowd-cart-pole | crowd-tiny | brain-cart-pole | brain-tiny\n");
    return 2;
}
