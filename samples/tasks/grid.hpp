// A rectangular grid world with optional walls between cells: the board of the hot plates, the
// mazes and the curiosity grid. Coordinates (x, y) are 0-based, x to the right, y downward.
#pragma once
#include <cstdint>
#include <vector>

#include "tasks/task.hpp"

namespace verve::tasks {

struct Cell {
    int x = 0;
    int y = 0;
    bool operator==(const Cell& o) const { return x == o.x && y == o.y; }
    bool operator!=(const Cell& o) const { return !(*this == o); }
};

// The thesis's action order for 2D tasks (the 1D tasks use Left, Right, Stay).
enum class Move : std::uint8_t { Left = 0, Right = 1, Up = 2, Down = 3, Stay = 4 };

class Grid {
public:
    static constexpr std::uint32_t kUnreachable = 0xFFFFFFFFu;

    Grid(int width, int height);  // throws std::invalid_argument unless both are >= 1

    int width() const { return width_; }
    int height() const { return height_; }
    bool contains(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }

    // A wall between column `column` and column + 1 on rows firstRow..lastRow (inclusive).
    void addWallRightOf(int column, int firstRow, int lastRow);
    // A wall between row `row` and row + 1 on columns firstColumn..lastColumn (inclusive).
    void addWallBelow(int row, int firstColumn, int lastColumn);

    // Where a move ends: into a wall or the border, the agent stays where it is.
    Cell move(Cell from, Move m) const;

    // Breadth-first shortest path in moves; kUnreachable when `to` cannot be reached.
    std::uint32_t shortestPath(Cell from, Cell to) const;

    // Sensor layout of a position: x then y (a 1-row grid has only x).
    void addPositionSensors(AgentDescriptor& desc, Sensors sensors) const;
    // Writes the position into the first discrete (or continuous) slots of `out`.
    void writePosition(Cell c, Sensors sensors, Observation& out) const;

private:
    bool blockedRight(int x, int y) const { return wallRight_[index(x, y)] != 0; }
    bool blockedBelow(int x, int y) const { return wallBelow_[index(x, y)] != 0; }
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y * width_ + x); }

    int width_;
    int height_;
    std::vector<std::uint8_t> wallRight_;  // no passage between (x, y) and (x + 1, y)
    std::vector<std::uint8_t> wallBelow_;  // no passage between (x, y) and (x, y + 1)
};

}  // namespace verve::tasks
