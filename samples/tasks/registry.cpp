#include "tasks/registry.hpp"

#include "tasks/bandit.hpp"
#include "tasks/corridor.hpp"
#include "tasks/cue_change.hpp"
#include "tasks/branched_plate.hpp"
#include "tasks/distractors.hpp"
#include "tasks/curiosity_grid.hpp"
#include "tasks/hot_plate.hpp"
#include "tasks/maze.hpp"
#include "tasks/sequential_actions.hpp"
#include "tasks/steering_car.hpp"

namespace verve::tasks {
namespace {

TaskFactory hotPlate(int dimensions, bool signaled, Sensors sensors) {
    return [=](std::uint64_t) {
        return std::make_unique<HotPlate>(HotPlateConfig{dimensions, signaled, sensors});
    };
}

TaskFactory maze(MazeLayout (*layout)(), Sensors sensors, bool planning) {
    return [=](std::uint64_t) {
        auto task = std::make_unique<Maze>(layout(), sensors);
        if (planning) {  // the original's measured planning run: model rate 1, plans of <= 50 steps
            task->settings().planning = true;
            task->settings().tauModel = 0.0f;
            task->settings().maxPlanningSteps = 50;
        }
        return task;
    };
}

TaskFactory distractors(std::uint32_t count) {
    return [=](std::uint64_t) { return std::make_unique<HotPlateAmongDistractors>(count); };
}

TaskFactory branchedPlate(bool branches) {
    return [=](std::uint64_t) { return std::make_unique<BranchedPlate>(branches); };
}

TaskFactory curiosityGrid(CuriosityAgent agent) {
    return [=](std::uint64_t) { return std::make_unique<CuriosityGrid>(agent); };
}

std::vector<TaskInfo> makeRegistry() {
    const Sensors D = Sensors::Discrete;
    const Sensors C = Sensors::Continuous;
    return {
        {"bandit", "10-armed bandit: one state, lever means ~N(0,1), payoff ~N(mean,1)",
         [](std::uint64_t seed) { return std::make_unique<Bandit>(seed); }, 2000, 1000, Metric::Reward},
        {"sequential-actions", "Suri & Schultz: 7 stimuli/actions, trained backwards in 100-trial blocks",
         [](std::uint64_t seed) { return std::make_unique<SequentialActions>(seed); }, 200, 700, Metric::Success},
        {"hot-plate-1d", "1D hot plate, 20 cells, both ends safe, discrete position", hotPlate(1, false, D), 300, 31,
         Metric::Steps},
        {"hot-plate-1d-continuous", "1D hot plate, continuous position (resolution 10)", hotPlate(1, false, C), 300,
         31, Metric::Steps},
        {"signaled-hot-plate-1d", "1D hot plate, one safe end named by a 2-valued signal, discrete position",
         hotPlate(1, true, D), 500, 81, Metric::Steps},
        {"signaled-hot-plate-1d-continuous", "1D signaled hot plate, continuous position (resolution 25)",
         hotPlate(1, true, C), 500, 81, Metric::Steps},
        {"hot-plate-2d", "2D hot plate, 20x20, all borders safe, discrete position", hotPlate(2, false, D), 300, 301,
         Metric::Steps},
        {"hot-plate-2d-continuous", "2D hot plate, continuous position (resolution 10)", hotPlate(2, false, C), 300,
         301, Metric::Steps},
        {"signaled-hot-plate-2d", "2D hot plate, one safe border named by a 4-valued signal, discrete position",
         hotPlate(2, true, D), 300, 1601, Metric::Steps},
        {"signaled-hot-plate-2d-continuous", "2D signaled hot plate, continuous position (resolution 25)",
         hotPlate(2, true, C), 300, 1601, Metric::Steps},
        // Many sensors: the signal must be read with the position among 2, 6 or 14 wandering ones.
        {"signaled-hot-plate-1d-2-distractors", "1D signaled hot plate, position + continuous signal + 2 distractors",
         distractors(2), 100, 301, Metric::Steps},
        {"signaled-hot-plate-1d-6-distractors", "1D signaled hot plate, position + continuous signal + 6 distractors",
         distractors(6), 100, 301, Metric::Steps},
        {"signaled-hot-plate-1d-14-distractors", "1D signaled hot plate, position + continuous signal + 14 distractors",
         distractors(14), 100, 301, Metric::Steps},
        {"signaled-hot-plate-1d-30-distractors", "1D signaled hot plate, position + continuous signal + 30 distractors",
         distractors(30), 100, 301, Metric::Steps},
        {"signaled-hot-plate-2d-branches", "2D signaled hot plate, move x move x pace as 3 action branches (3x3x2)",
         branchedPlate(true), 100, 301, Metric::Steps},
        {"signaled-hot-plate-2d-18-moves", "2D signaled hot plate, the same 18 combined moves as one action set",
         branchedPlate(false), 100, 301, Metric::Steps},
        // Continuous actions: the same car steered and throttled continuously, or by 3 x 3 branches.
        {"steering-car", "a car drives to random targets, steering and throttle as 2 continuous actions",
         [](std::uint64_t) { return std::make_unique<SteeringCar>(SteeringCar::Controls::Continuous); }, 20, 301,
         Metric::Steps},
        {"steering-car-branches", "the same car, steering and throttle as 2 action branches of 3 choices",
         [](std::uint64_t) { return std::make_unique<SteeringCar>(SteeringCar::Controls::Branches); }, 20, 301,
         Metric::Steps},
        {"maze1", "2D maze #1 (shortest path 22), discrete position", maze(maze1Layout, D, false), 50, 100,
         Metric::Steps},
        {"maze1-continuous", "2D maze #1, continuous position (resolution 15)", maze(maze1Layout, C, false), 50, 100,
         Metric::Steps},
        {"maze2", "2D maze #2 (shortest path 25), discrete position, no planning", maze(maze2Layout, D, false), 10,
         51, Metric::Steps},
        {"maze2-continuous", "2D maze #2, continuous position (resolution 15)", maze(maze2Layout, C, false), 10, 51,
         Metric::Steps},
        {"maze2-planning", "2D maze #2, discrete position, planning <= 50 steps, model rate 1",
         maze(maze2Layout, D, true), 10, 51, Metric::Steps},
        {"curiosity-grid-rl", "curiosity grid (0.1 near, 1.0 far), plain RL", curiosityGrid(CuriosityAgent::Rl), 30,
         81, Metric::Reward},
        {"curiosity-grid-planning", "curiosity grid, planning <= 50 steps",
         curiosityGrid(CuriosityAgent::Planning), 30, 81, Metric::Reward},
        {"curiosity-grid-curious", "curiosity grid, planning <= 50 steps plus curiosity",
         curiosityGrid(CuriosityAgent::Curious), 30, 81, Metric::Reward},
        // Long horizon: -1 per step for dozens of steps before the only reward.
        {"corridor", "40-cell continuous corridor, -1 per step to the far end (optimum 39), no planning",
         [](std::uint64_t) { return std::make_unique<Corridor>(); }, 10, 100, Metric::Steps},
        {"corridor-planning", "the corridor with planning <= 50 steps, model rate 1",
         [](std::uint64_t) {
             auto task = std::make_unique<Corridor>();
             task->settings().planning = true;
             task->settings().tauModel = 0.0f;
             task->settings().maxPlanningSteps = 50;
             return task;
         },
         10, 100, Metric::Steps},
        // A changing world: the rules change once the agent has learned them.
        {"cue-change", "8 cues -> 5 actions (+1/-1); 4 cues change their correct action at trial 1000",
         [](std::uint64_t seed) { return std::make_unique<CueChange>(seed); }, 20, 2000, Metric::Success},
        // A world that changes: bounded actor weights (3), so the old path's habit can be unlearned.
        // With the defaults some runs keep walking the old path for dozens of trials (docs/experiments.md).
        {"maze1-moving-goal", "maze #1, discrete position, actor bound 3; the goal moves to (0, 9) at trial 50",
         [](std::uint64_t) {
             auto task = std::make_unique<Maze>(maze1MovingGoalLayout(), Sensors::Discrete);
             task->settings().policyWeightBound = 3.0f;
             return task;
         },
         50, 150, Metric::Steps},
        {"swapping-hot-plate-1d", "1D hot plate, left end safe until trial 100, then only the right end",
         [](std::uint64_t) { return std::make_unique<HotPlate>(HotPlateConfig{1, false, Sensors::Discrete, 20, 200, 100}); },
         100, 300, Metric::Steps},
    };
}

}  // namespace

const std::vector<TaskInfo>& taskRegistry() {
    static const std::vector<TaskInfo> registry = makeRegistry();
    return registry;
}

const TaskInfo* findTask(const std::string& name) {
    for (const TaskInfo& info : taskRegistry()) {
        if (info.name == name) return &info;
    }
    return nullptr;
}

const char* metricName(Metric metric) {
    switch (metric) {
        case Metric::Steps: return "steps";
        case Metric::Reward: return "reward";
        default: return "success";
    }
}

}  // namespace verve::tasks
