// 2D maze #2 without planning: the original library averaged 1124 steps over trials 41-50
// (shortest path 25). (The planning and curiosity tests of issue #4 come with the planner.)
#include <gtest/gtest.h>

#include "learning_window.hpp"

using namespace verve::tasks;
using namespace verve::tasks::testing;

TEST(MazeLearning, Maze2WithoutPlanningBeatsTheOriginal) {
    const LearningCurve c = learn("maze2", 20, 51);
    const Window w = windowOf(c, 41, 51);
    print("maze2 trials 41-50", w);
    EXPECT_LE(w.steps, 1124.0);
    EXPECT_GE(windowOf(c, 41, 51).reward, -1124.0);
}
