// Demonstrated continuous actions (docs/teaching.md): the 1-D reach task (x moves by 0.1 a per
// step, every step costs |x|; the bindings' continuous-action checks use it), learned by an agent
// that first watched a teacher steer for a few episodes, beside one that did not. Thresholds come
// from measurements over these seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "tasks/driver.hpp"
#include "tasks/settings.hpp"
#include "tasks/steering_car.hpp"
#include "tasks/task_rng.hpp"
#include "verve/agent.hpp"

using namespace verve;

namespace {

constexpr int kSteps = 100;

AgentDescriptor reacher(std::uint64_t seed) {
    AgentDescriptor d;
    d.addContinuousSensor();
    d.numActions = 1;
    d.continuousActions = 1;
    d.seed = seed;
    return d;
}

class Starts {
public:
    explicit Starts(std::uint32_t seed) : state_(seed) {}
    float next() {
        state_ = state_ * 1664525u + 1013904223u;
        return static_cast<float>(state_ >> 8) / 16777216.0f * 2.0f - 1.0f;
    }

private:
    std::uint32_t state_;
};

float teacher(float x) { return std::clamp(-10.0f * x, -1.0f, 1.0f); }

enum class Driver { Agent, Teacher, TeacherUnnamed };  // TeacherUnnamed: the discrete action only

// One episode from `x`; with a teacher, the teacher steers. Returns the summed costs.
float episode(Agent& agent, float x, Driver driver) {
    Observation obs(agent.descriptor());
    float reward = 0.0f, cost = 0.0f;
    for (int t = 0; t < kSteps; ++t) {
        obs.setContinuous(0, x);
        float a;
        if (driver == Driver::Teacher) {
            a = teacher(x);
            agent.updateDemonstrated(reward, obs.view(), 0.05f, 0, ContinuousActionView{&a, 1});
        } else if (driver == Driver::TeacherUnnamed) {
            a = teacher(x);
            agent.updateDemonstrated(reward, obs.view(), 0.05f, 0);  // the agent plays its means
        } else {
            agent.update(reward, obs, 0.05f);
            a = agent.continuousAction()[0];
        }
        x = std::clamp(x + 0.1f * a, -1.0f, 1.0f);
        reward = -std::fabs(x);
        cost += std::fabs(x);
    }
    agent.truncateEpisode(reward);
    return cost;
}

// Mean greedy cost per episode over 20 fixed starts, after `demonstrated` taught and `own` episodes.
float greedyCost(std::uint64_t seed, int demonstrated, int own, Driver teacherKind) {
    Agent agent(reacher(seed));
    Starts starts(static_cast<std::uint32_t>(seed));
    for (int e = 0; e < demonstrated; ++e) episode(agent, starts.next(), teacherKind);
    for (int e = 0; e < own; ++e) episode(agent, starts.next(), Driver::Agent);
    agent.setActionSelection(ActionSelection::Greedy);
    agent.setLearning(false);
    Starts probe(12345);
    float total = 0.0f;
    for (int e = 0; e < 20; ++e) total += episode(agent, probe.next(), Driver::Agent);
    return total / 20.0f;
}

// Over seeds 1-8.
float meanOverSeeds(int demonstrated, int own, Driver teacherKind = Driver::Teacher) {
    float sum = 0.0f;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) sum += greedyCost(seed, demonstrated, own, teacherKind);
    return sum / 8.0f;
}

// The teacher's own cost over the probe's starts.
float teacherCost() {
    Starts probe(12345);
    float total = 0.0f;
    for (int e = 0; e < 20; ++e) {
        float x = probe.next();
        for (int t = 0; t < kSteps; ++t) {
            x = std::clamp(x + 0.1f * teacher(x), -1.0f, 1.0f);
            total += std::fabs(x);
        }
    }
    return total / 20.0f;
}

}  // namespace

TEST(ContinuousDemonstrationLearning, ADemonstratedReachIsLearnedSooner) {
    std::printf("[ measured ] the teacher's cost per episode: %.2f\n", teacherCost());
    float taught[3], alone[3];
    const int own[3] = {0, 100, 400};
    for (int i = 0; i < 3; ++i) {
        taught[i] = meanOverSeeds(10, own[i]);
        alone[i] = meanOverSeeds(0, own[i]);
        std::printf("[ measured ] after %d own episodes: %.2f with 10 demonstrated, %.2f without\n", own[i], taught[i], alone[i]);
    }
    const float unnamed = meanOverSeeds(10, 0, Driver::TeacherUnnamed);
    std::printf("[ measured ] 10 demonstrated with the discrete action only (the means played): %.2f\n", unnamed);
    // Measured: the teacher 1.78; after 0 own episodes 4.51 taught, 53.16 alone; after 100, 2.99 and
    // 5.35; after 400, 2.46 and 2.57. Discrete-only demonstrations teach the reach nothing (53.16).
    EXPECT_LE(taught[0], 7.0f);
    EXPECT_GE(alone[0], 30.0f);
    EXPECT_LE(taught[1], alone[1] - 1.5f);
    EXPECT_LE(taught[2], alone[2] + 0.3f);  // and it ends as well
    EXPECT_GE(unnamed, 30.0f);
}

namespace {

// One steering-car trial driven by the scripted driver, its steering and throttle demonstrated.
std::uint32_t demonstratedCarTrial(Agent& agent, verve::tasks::SteeringCar& car, std::uint64_t seed) {
    using verve::tasks::SteeringCar;
    car.beginTrial(seed);
    Observation obs(agent.descriptor());
    float reward = 0.0f;
    for (std::uint32_t step = 1; step <= SteeringCar::kMaxSteps; ++step) {
        car.observe(obs);
        double steer = 0, throttle = 0;
        car.scriptedControls(steer, throttle);
        const float values[2] = {std::clamp(static_cast<float>(steer), -1.0f, 1.0f),
                                 std::clamp(static_cast<float>(throttle), -1.0f, 1.0f)};
        agent.updateDemonstrated(reward, obs.view(), car.agentStep(), 0, ContinuousActionView{values, 2});
        const verve::tasks::StepResult r = car.drive(values[0], values[1]);
        if (r.terminal) {
            agent.endEpisode(r.reward);
            return step;
        }
        reward = r.reward;
    }
    agent.truncateEpisode(reward);
    return SteeringCar::kMaxSteps;
}

// Steps per trial of the learning car over 300 trials (the first `shown` driven by the script),
// averaged over runs 1..runs at the library's defaults less the `cleared` adaptation bits, with the
// defaults table's trial seeds.
std::vector<double> carCurve(std::uint32_t shown, std::uint64_t runs, std::uint32_t cleared = 0) {
    using namespace verve::tasks;
    std::vector<double> steps(300, 0.0);
    for (std::uint64_t run = 1; run <= runs; ++run) {
        SteeringCar car(SteeringCar::Controls::Continuous);
        AgentDescriptor d = atLibraryDefaults(car.agentDescriptor());
        d.seed = run;
        d.adaptation &= ~cleared;
        Agent agent(d);
        for (std::uint32_t t = 0; t < 300; ++t) {
            const std::uint64_t seed = mixSeed(run, t);
            steps[t] += t < shown ? demonstratedCarTrial(agent, car, seed) : runTrial(agent, car, seed).steps;
        }
    }
    for (double& s : steps) s /= static_cast<double>(runs);
    return steps;
}

double meanOf(const std::vector<double>& v, std::size_t first, std::size_t last) {
    double sum = 0.0;
    for (std::size_t i = first; i < last; ++i) sum += v[i];
    return sum / static_cast<double>(last - first);
}

}  // namespace

// The scripted driver's steps per trial on the same trials (runs 1..runs, trials 0..299).
double scriptedCarSteps(std::uint64_t runs) {
    using namespace verve::tasks;
    SteeringCar car(SteeringCar::Controls::Continuous);
    double steps = 0.0;
    for (std::uint64_t run = 1; run <= runs; ++run) {
        for (std::uint32_t t = 0; t < 300; ++t) {
            car.beginTrial(mixSeed(run, t));
            std::uint32_t n = 0;
            while (n < SteeringCar::kMaxSteps) {
                double steer = 0, throttle = 0;
                car.scriptedControls(steer, throttle);
                ++n;
                if (car.drive(steer, throttle).terminal) break;
            }
            steps += n;
        }
    }
    return steps / (300.0 * static_cast<double>(runs));
}

// The first trial (from 1) after which the mean of the last 20 trials, all after the first `own`
// (the demonstrated ones, which the script drove), is at most `bar`; 0: never.
std::size_t trialsToReach(const std::vector<double>& c, double bar, std::size_t own) {
    for (std::size_t t = own + 20; t <= c.size(); ++t) {
        if (meanOf(c, t - 20, t) <= bar) return t;
    }
    return 0;
}

// The steering car (docs/experiments.md, "Continuous actions"), shown the scripted driver's
// continuous steering and throttle for its first trials, beside the car that learns alone. With
// one lattice over its 3 sensors (the pairs beside it cleared), as when this was measured, the car
// alone never reached the script; at defaults it does by trial 87 (alone 72.7 steps on trials
// 91-120 and 63.5 on 271-300; shown 10 trials 78.0 and 65.2, at the script's from trial 90; shown
// 30: 65.7 and 65.1, from trial 63): a 77-step driver then has little left to teach, so the bars
// on what showing adds are kept on the slower learner, and at defaults the shown car must still
// beat its teacher.
TEST(ContinuousDemonstrationLearning, TheSteeringCarShownTheScriptedDriverBeatsItSooner) {
    const std::uint64_t runs = 20;
    const double scripted = scriptedCarSteps(runs);
    std::printf("[ measured ] the scripted driver: %.1f steps per trial\n", scripted);
    const std::vector<double> atDefaults = carCurve(10, runs);
    std::printf("[ measured ] at defaults, shown 10 trials: steps per trial 271-300 %.1f\n", meanOf(atDefaults, 270, 300));
    EXPECT_LE(meanOf(atDefaults, 270, 300), scripted);
    double late[3] = {}, early[3] = {};
    std::size_t reach[3] = {};
    const std::uint32_t shown[3] = {0, 10, 30};
    for (int i = 0; i < 3; ++i) {
        const std::vector<double> c = carCurve(shown[i], runs, Adaptation::PairsBeside);
        early[i] = meanOf(c, 90, 120);
        late[i] = meanOf(c, 270, 300);
        reach[i] = trialsToReach(c, scripted, shown[i]);
        std::printf("[ measured ] shown %u trials: steps per trial 91-120 %.1f, 271-300 %.1f; 20 trials' mean at or below "
                    "the script's after trial %zu (0: never)\n",
                    shown[i], early[i], late[i], reach[i]);
    }
    // Measured (runs 1-20): the script 77.2; alone 111.9 and 82.4, never at the script's; shown 10
    // trials 90.8 and 67.6, at the script's from trial 136; shown 30: 99.5 and 69.5, from trial 180.
    EXPECT_LE(late[1], scripted);
    EXPECT_LE(late[1], late[0] - 8.0);
    EXPECT_LE(early[1], early[0] - 8.0);
    EXPECT_GT(reach[1], 0u);
}
