#include <gtest/gtest.h>

#include "tasks/maze.hpp"

using namespace verve::tasks;

TEST(Maze1, LayoutAndShortestPath) {
    const MazeLayout m = maze1Layout();
    EXPECT_EQ(m.grid.shortestPath(m.start, m.goal), 22u);
    for (int y = 0; y <= 8; ++y) EXPECT_EQ(m.grid.move({6, y}, Move::Right), (Cell{6, y})) << "row " << y;
    EXPECT_EQ(m.grid.move({6, 9}, Move::Right), (Cell{7, 9}));
    EXPECT_EQ(m.grid.move({7, 4}, Move::Left), (Cell{7, 4}));
}

TEST(Maze2, LayoutAndShortestPath) {
    const MazeLayout m = maze2Layout();
    EXPECT_EQ(m.start, (Cell{1, 1}));
    EXPECT_EQ(m.goal, (Cell{8, 1}));
    EXPECT_EQ(m.grid.shortestPath(m.start, m.goal), 25u);
    EXPECT_EQ(m.grid.move({3, 0}, Move::Right), (Cell{4, 0}));  // 3|4 open on row 0
    for (int y = 1; y <= 9; ++y) EXPECT_EQ(m.grid.move({3, y}, Move::Right), (Cell{3, y}));
    for (int y = 0; y <= 8; ++y) {
        EXPECT_EQ(m.grid.move({5, y}, Move::Right), (Cell{5, y}));
        EXPECT_EQ(m.grid.move({8, y}, Move::Left), (Cell{8, y}));
    }
    EXPECT_EQ(m.grid.move({5, 9}, Move::Right), (Cell{6, 9}));
    EXPECT_EQ(m.grid.move({7, 9}, Move::Right), (Cell{8, 9}));
}

TEST(Maze, RewardsTerminalAndReset) {
    Maze maze(maze1Layout(), Sensors::Discrete);
    maze.beginTrial(7);
    EXPECT_EQ(maze.position(), (Cell{1, 1}));
    EXPECT_EQ(maze.optimalSteps(), 22u);
    // Walk the shortest path: down 8, right 6, up 8.
    int steps = 0;
    StepResult r;
    for (int i = 0; i < 8; ++i, ++steps) r = maze.act(3);
    for (int i = 0; i < 6; ++i, ++steps) r = maze.act(1);
    for (int i = 0; i < 7; ++i, ++steps) {
        r = maze.act(2);
        EXPECT_FLOAT_EQ(r.reward, -1.0f);
        EXPECT_FALSE(r.terminal);
    }
    r = maze.act(2);
    ++steps;
    EXPECT_EQ(steps, 22);
    EXPECT_TRUE(r.terminal);
    EXPECT_FLOAT_EQ(r.reward, 1.0f);
    EXPECT_TRUE(maze.succeeded());
    maze.beginTrial(8);
    EXPECT_EQ(maze.position(), (Cell{1, 1}));
    EXPECT_FALSE(maze.succeeded());
}

TEST(Maze, SettingsAndSensors) {
    Maze d(maze2Layout(), Sensors::Discrete);
    Maze c(maze2Layout(), Sensors::Continuous);
    EXPECT_EQ(d.name(), "maze2");
    EXPECT_EQ(c.name(), "maze2-continuous");
    EXPECT_EQ(d.agentDescriptor().discreteSensors, (std::vector<std::uint32_t>{10, 10}));
    EXPECT_EQ(c.agentDescriptor().resolution, 15u);
    EXPECT_EQ(d.maxStepsPerTrial(), 10000u);
    verve::Observation obs(c.agentDescriptor());
    c.beginTrial(0);
    c.observe(obs);
    EXPECT_NEAR(obs.continuous[0], -1.0f + 2.0f / 9.0f, 1e-6f);
    EXPECT_THROW(c.act(5), std::invalid_argument);
}
