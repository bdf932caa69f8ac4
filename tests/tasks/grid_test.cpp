#include <gtest/gtest.h>

#include <stdexcept>

#include "tasks/grid.hpp"

using namespace verve::tasks;

TEST(CellToSensor, MapsCellsEvenlyOntoMinusOneToOne) {
    EXPECT_FLOAT_EQ(cellToSensor(0, 20), -1.0f);
    EXPECT_FLOAT_EQ(cellToSensor(19, 20), 1.0f);
    EXPECT_FLOAT_EQ(cellToSensor(1, 3), 0.0f);
    EXPECT_NEAR(cellToSensor(1, 10), -1.0f + 2.0f / 9.0f, 1e-6f);
}

TEST(Grid, BordersKeepTheAgentInside) {
    Grid g(5, 4);
    EXPECT_EQ(g.move({0, 0}, Move::Left), (Cell{0, 0}));
    EXPECT_EQ(g.move({0, 0}, Move::Up), (Cell{0, 0}));
    EXPECT_EQ(g.move({4, 3}, Move::Right), (Cell{4, 3}));
    EXPECT_EQ(g.move({4, 3}, Move::Down), (Cell{4, 3}));
    EXPECT_EQ(g.move({2, 2}, Move::Left), (Cell{1, 2}));
    EXPECT_EQ(g.move({2, 2}, Move::Right), (Cell{3, 2}));
    EXPECT_EQ(g.move({2, 2}, Move::Up), (Cell{2, 1}));
    EXPECT_EQ(g.move({2, 2}, Move::Down), (Cell{2, 3}));
    EXPECT_EQ(g.move({2, 2}, Move::Stay), (Cell{2, 2}));
}

TEST(Grid, WallsBlockBothDirectionsOnlyOnTheirRows) {
    Grid g(4, 4);
    g.addWallRightOf(1, 0, 2);  // between columns 1 and 2, rows 0-2
    g.addWallBelow(0, 3, 3);    // between rows 0 and 1 in column 3
    EXPECT_EQ(g.move({1, 0}, Move::Right), (Cell{1, 0}));
    EXPECT_EQ(g.move({2, 2}, Move::Left), (Cell{2, 2}));
    EXPECT_EQ(g.move({1, 3}, Move::Right), (Cell{2, 3}));  // row 3 is open
    EXPECT_EQ(g.move({3, 0}, Move::Down), (Cell{3, 0}));
    EXPECT_EQ(g.move({3, 1}, Move::Up), (Cell{3, 1}));
    EXPECT_EQ(g.move({2, 0}, Move::Down), (Cell{2, 1}));
}

TEST(Grid, ShortestPathGoesAroundWalls) {
    Grid g(4, 4);
    EXPECT_EQ(g.shortestPath({0, 0}, {3, 3}), 6u);
    EXPECT_EQ(g.shortestPath({2, 1}, {2, 1}), 0u);
    g.addWallRightOf(1, 0, 2);
    EXPECT_EQ(g.shortestPath({1, 0}, {2, 0}), 7u);  // down to row 3, across, back up
    g.addWallRightOf(1, 3, 3);
    EXPECT_EQ(g.shortestPath({1, 0}, {2, 0}), Grid::kUnreachable);
    EXPECT_EQ(g.shortestPath({0, 0}, {9, 9}), Grid::kUnreachable);
}

TEST(Grid, RejectsBadSizesAndWallsOutside) {
    EXPECT_THROW(Grid(0, 3), std::invalid_argument);
    Grid g(3, 3);
    EXPECT_THROW(g.addWallRightOf(2, 0, 0), std::invalid_argument);  // no column to the right
    EXPECT_THROW(g.addWallRightOf(0, 2, 1), std::invalid_argument);
    EXPECT_THROW(g.addWallBelow(0, 0, 3), std::invalid_argument);
    EXPECT_EQ(g.shortestPath({0, 0}, {2, 2}), 4u);  // the failed calls added nothing
}

TEST(Grid, PositionSensorsFollowTheSensorKind) {
    Grid line(20, 1);
    Grid plate(20, 10);
    verve::AgentDescriptor d1, d2, c2;
    line.addPositionSensors(d1, Sensors::Discrete);
    plate.addPositionSensors(d2, Sensors::Discrete);
    plate.addPositionSensors(c2, Sensors::Continuous);
    EXPECT_EQ(d1.discreteSensors, (std::vector<std::uint32_t>{20}));
    EXPECT_EQ(d2.discreteSensors, (std::vector<std::uint32_t>{20, 10}));
    EXPECT_EQ(c2.continuousSensors.size(), 2u);

    verve::Observation obs(c2);
    plate.writePosition({19, 0}, Sensors::Continuous, obs);
    EXPECT_FLOAT_EQ(obs.continuous[0], 1.0f);
    EXPECT_FLOAT_EQ(obs.continuous[1], -1.0f);
}
