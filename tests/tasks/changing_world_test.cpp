// The tasks whose rules change: they change exactly when and how they say.
#include <gtest/gtest.h>

#include "tasks/corridor.hpp"
#include "tasks/cue_change.hpp"
#include "tasks/hot_plate.hpp"
#include "tasks/maze.hpp"

using namespace verve::tasks;

TEST(CueChange, HalfTheCuesGetAnotherAnswerAtTheChangeTrial) {
    CueChange task(3, CueChangeConfig{8, 5, 10, 4});
    std::vector<std::uint32_t> before;
    for (int t = 0; t < 10; ++t) {
        task.beginTrial(t);
        if (t == 9) {
            for (std::uint32_t c = 0; c < 8; ++c) before.push_back(task.correctAction(c));
        }
    }
    task.beginTrial(10);
    int changed = 0;
    for (std::uint32_t c = 0; c < 8; ++c) {
        EXPECT_LT(task.correctAction(c), 5u);
        changed += task.correctAction(c) != before[c];
    }
    EXPECT_EQ(changed, 4);
    const StepResult right = task.act(task.correctAction(task.cue()));
    EXPECT_TRUE(right.terminal);
    EXPECT_EQ(right.reward, 1.0f);
    EXPECT_TRUE(task.succeeded());
    EXPECT_EQ(task.act((task.correctAction(task.cue()) + 1) % 5).reward, -1.0f);
    EXPECT_THROW(CueChange(1, CueChangeConfig{4, 5, 10, 5}), std::invalid_argument);
}

TEST(MovingGoalMaze, TheGoalMovesAtItsTrial) {
    Maze maze(maze1MovingGoalLayout(), Sensors::Discrete);
    for (int t = 0; t < 50; ++t) maze.beginTrial(0);
    EXPECT_EQ(maze.optimalSteps(), 22u);
    maze.beginTrial(0);  // trial 50
    EXPECT_EQ(maze.optimalSteps(), 9u);
    StepResult r;
    for (int i = 0; i < 8; ++i) r = maze.act(static_cast<std::uint32_t>(Move::Down));
    EXPECT_FALSE(r.terminal);
    r = maze.act(static_cast<std::uint32_t>(Move::Left));
    EXPECT_TRUE(r.terminal);
    EXPECT_TRUE(maze.succeeded());
}

TEST(SwappingHotPlate, TheSafeEndSwapsAtItsTrial) {
    HotPlate plate(HotPlateConfig{1, false, Sensors::Discrete, 20, 200, 3});
    EXPECT_EQ(plate.name(), "swapping-hot-plate-1d");
    for (int t = 0; t < 3; ++t) {
        plate.beginTrial(t);
        EXPECT_TRUE(plate.isSafe(Cell{0, 0}));
        EXPECT_FALSE(plate.isSafe(Cell{19, 0}));
    }
    plate.beginTrial(3);
    EXPECT_FALSE(plate.isSafe(Cell{0, 0}));
    EXPECT_TRUE(plate.isSafe(Cell{19, 0}));
    EXPECT_THROW(HotPlate(HotPlateConfig{2, false, Sensors::Discrete, 20, 200, 3}), std::invalid_argument);
}

TEST(Corridor, MinusOnePerStepUntilTheFarEnd) {
    Corridor corridor(5);
    corridor.beginTrial(0);
    EXPECT_EQ(corridor.optimalSteps(), 4u);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(corridor.act(1).reward, -1.0f);
    const StepResult end = corridor.act(1);
    EXPECT_TRUE(end.terminal);
    EXPECT_EQ(end.reward, 1.0f);
}
