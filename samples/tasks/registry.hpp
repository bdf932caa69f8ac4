// Every task by name: what the runner and verve-experiments list and run. Each entry carries the
// full-size experiment of the original library (runs x trials) and the curve that matters.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "tasks/driver.hpp"

namespace verve::tasks {

enum class Metric : std::uint8_t {
    Steps,    // steps to the goal per trial (lower is better)
    Reward,   // reward sum per trial (higher is better)
    Success,  // fraction of successful trials (higher is better)
};

struct TaskInfo {
    std::string name;
    std::string description;
    TaskFactory make;
    std::uint32_t runs;    // full-size experiment
    std::uint32_t trials;
    Metric metric;
};

const std::vector<TaskInfo>& taskRegistry();
// nullptr when no task has that name.
const TaskInfo* findTask(const std::string& name);

const char* metricName(Metric metric);

}  // namespace verve::tasks
