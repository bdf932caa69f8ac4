#include "catalog.hpp"

#include "scene_registry.hpp"
#include "tasks/registry.hpp"

namespace verve::demo {

namespace {

Runnable fromTask(const tasks::TaskInfo& t) {
    Runnable r{t.name, "task", t.description, t.make, t.trials, "", true, false, {}, {}};
    switch (t.metric) {
        case tasks::Metric::Steps:
            r.metricLabel = "steps per trial";
            r.higherIsBetter = false;
            r.metric = [](const tasks::TrialResult& res, const tasks::Environment&) { return double(res.steps); };
            break;
        case tasks::Metric::Reward:
            r.metricLabel = "reward per trial";
            r.metric = [](const tasks::TrialResult& res, const tasks::Environment&) { return res.rewardSum; };
            break;
        case tasks::Metric::Success:
            r.metricLabel = "success (1 = trial succeeded)";
            r.metric = [](const tasks::TrialResult& res, const tasks::Environment&) {
                return res.succeeded ? 1.0 : 0.0;
            };
            break;
    }
    return r;
}

Runnable fromScene(const scenes::SceneInfo& s) {
    auto make = s.make;
    Runnable r{s.name, "scene", s.description, [make](std::uint64_t) { return make(); }, s.trials, "", true,
               s.capMeansSolved, s.sensorNames, {}};
    switch (s.metric) {
        case scenes::SceneMetric::RewardPerStep:
            r.metricLabel = "mean reward per step";
            r.metric = [](const tasks::TrialResult& res, const tasks::Environment&) {
                return res.steps > 0 ? res.rewardSum / res.steps : 0.0;
            };
            break;
        case scenes::SceneMetric::BalanceSeconds:
            r.metricLabel = "seconds balanced";
            r.metric = [](const tasks::TrialResult& res, const tasks::Environment& env) {
                return res.steps * static_cast<double>(env.agentStep());
            };
            break;
    }
    return r;
}

std::vector<Runnable> build() {
    std::vector<Runnable> all;
    for (const scenes::SceneInfo& s : scenes::sceneRegistry()) all.push_back(fromScene(s));
    for (const tasks::TaskInfo& t : tasks::taskRegistry()) all.push_back(fromTask(t));
    return all;
}

}  // namespace

const std::vector<Runnable>& catalog() {
    static const std::vector<Runnable> all = build();
    return all;
}

const Runnable* findRunnable(const std::string& name) {
    for (const Runnable& r : catalog())
        if (r.name == name) return &r;
    return nullptr;
}

}  // namespace verve::demo
