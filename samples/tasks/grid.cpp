#include "tasks/grid.hpp"

#include <deque>
#include <stdexcept>
#include <string>

namespace verve::tasks {

float cellToSensor(int cell, int cells) {
    if (cells < 2) return 0.0f;
    return -1.0f + static_cast<float>(cell) * 2.0f / static_cast<float>(cells - 1);
}

Grid::Grid(int width, int height) : width_(width), height_(height) {
    if (width < 1 || height < 1) {
        throw std::invalid_argument("Grid: width and height must be >= 1, got " + std::to_string(width) +
                                    "x" + std::to_string(height));
    }
    wallRight_.assign(static_cast<std::size_t>(width * height), 0);
    wallBelow_.assign(static_cast<std::size_t>(width * height), 0);
}

void Grid::addWallRightOf(int column, int firstRow, int lastRow) {
    if (column < 0 || column >= width_ - 1 || firstRow < 0 || lastRow >= height_ || firstRow > lastRow) {
        throw std::invalid_argument("Grid::addWallRightOf: wall outside the grid");
    }
    for (int y = firstRow; y <= lastRow; ++y) wallRight_[index(column, y)] = 1;
}

void Grid::addWallBelow(int row, int firstColumn, int lastColumn) {
    if (row < 0 || row >= height_ - 1 || firstColumn < 0 || lastColumn >= width_ ||
        firstColumn > lastColumn) {
        throw std::invalid_argument("Grid::addWallBelow: wall outside the grid");
    }
    for (int x = firstColumn; x <= lastColumn; ++x) wallBelow_[index(x, row)] = 1;
}

Cell Grid::move(Cell from, Move m) const {
    Cell to = from;
    switch (m) {
        case Move::Left: to.x -= 1; break;
        case Move::Right: to.x += 1; break;
        case Move::Up: to.y -= 1; break;
        case Move::Down: to.y += 1; break;
        case Move::Stay: return from;
    }
    if (!contains(to)) return from;
    if (m == Move::Left && blockedRight(to.x, to.y)) return from;
    if (m == Move::Right && blockedRight(from.x, from.y)) return from;
    if (m == Move::Up && blockedBelow(to.x, to.y)) return from;
    if (m == Move::Down && blockedBelow(from.x, from.y)) return from;
    return to;
}

std::uint32_t Grid::shortestPath(Cell from, Cell to) const {
    if (!contains(from) || !contains(to)) return kUnreachable;
    std::vector<std::uint32_t> dist(static_cast<std::size_t>(width_ * height_), kUnreachable);
    std::deque<Cell> frontier{from};
    dist[index(from.x, from.y)] = 0;
    while (!frontier.empty()) {
        const Cell c = frontier.front();
        frontier.pop_front();
        if (c == to) return dist[index(c.x, c.y)];
        for (Move m : {Move::Left, Move::Right, Move::Up, Move::Down}) {
            const Cell n = move(c, m);
            std::uint32_t& d = dist[index(n.x, n.y)];
            if (d == kUnreachable) {
                d = dist[index(c.x, c.y)] + 1;
                frontier.push_back(n);
            }
        }
    }
    return kUnreachable;
}

void Grid::addPositionSensors(AgentDescriptor& desc, Sensors sensors) const {
    const int axes[2] = {width_, height_};
    const int count = height_ > 1 ? 2 : 1;
    for (int a = 0; a < count; ++a) {
        if (sensors == Sensors::Discrete) {
            desc.addDiscreteSensor(static_cast<std::uint32_t>(axes[a]));
        } else {
            desc.addContinuousSensor();
        }
    }
}

void Grid::writePosition(Cell c, Sensors sensors, Observation& out) const {
    const bool twoD = height_ > 1;
    if (sensors == Sensors::Discrete) {
        out.setDiscrete(0, c.x);
        if (twoD) out.setDiscrete(1, c.y);
    } else {
        out.setContinuous(0, cellToSensor(c.x, width_));
        if (twoD) out.setContinuous(1, cellToSensor(c.y, height_));
    }
}

}  // namespace verve::tasks
