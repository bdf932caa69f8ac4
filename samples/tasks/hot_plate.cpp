#include "tasks/hot_plate.hpp"

#include <algorithm>
#include <stdexcept>

#include "tasks/task_rng.hpp"

namespace verve::tasks {
namespace {

constexpr Move k1DMoves[] = {Move::Left, Move::Right, Move::Stay};

int signalValues(const HotPlateConfig& c) { return c.signaled ? 2 * c.dimensions : c.swapTrial > 0 ? 2 : 1; }

}  // namespace

HotPlate::HotPlate(const HotPlateConfig& config)
    : config_(config), grid_(config.size, config.dimensions == 2 ? config.size : 1) {
    if (config.dimensions != 1 && config.dimensions != 2) {
        throw std::invalid_argument("HotPlate: dimensions must be 1 or 2");
    }
    if (config.size < 3) throw std::invalid_argument("HotPlate: size must be >= 3");
    if (config.maxSteps == 0) throw std::invalid_argument("HotPlate: maxSteps must be >= 1");
    if (config.swapTrial > 0 && (config.dimensions != 1 || config.signaled)) {
        throw std::invalid_argument("HotPlate: only an unsignaled 1D plate can swap its safe end");
    }

    // Thesis figures 18, 20, 22, 26: policy multiplier 10; continuous resolution 10 (plain) or
    // 25 (signaled); time step and tau_value 0.1 s; the rest are the library defaults.
    grid_.addPositionSensors(settings_, config.sensors);
    if (config.signaled) settings_.addDiscreteSensor(static_cast<std::uint32_t>(signalValues(config)));
    settings_.numActions = config.dimensions == 1 ? 3 : 5;
    settings_.policyMultiplier = 10.0f;
    settings_.tauValue = 0.1f;
    settings_.resolution = config.signaled ? 25 : 10;
}

std::string HotPlate::name() const {
    std::string n = config_.signaled ? "signaled-hot-plate-" : config_.swapTrial > 0 ? "swapping-hot-plate-" : "hot-plate-";
    n += config_.dimensions == 1 ? "1d" : "2d";
    if (config_.sensors == Sensors::Continuous) n += "-continuous";
    return n;
}

bool HotPlate::isSafe(Cell c) const {
    const int last = config_.size - 1;
    if (!oneSafeEdge()) {
        return c.x == 0 || c.x == last || (config_.dimensions == 2 && (c.y == 0 || c.y == last));
    }
    switch (signal_) {
        case 0: return c.x == 0;
        case 1: return c.x == last;
        case 2: return c.y == 0;
        default: return c.y == last;
    }
}

std::uint32_t HotPlate::distanceToSafety(Cell c) const {
    const int last = config_.size - 1;
    int d = 0;
    if (!oneSafeEdge()) {
        d = std::min(c.x, last - c.x);
        if (config_.dimensions == 2) d = std::min({d, c.y, last - c.y});
    } else {
        const int perSignal[4] = {c.x, last - c.x, c.y, last - c.y};
        d = perSignal[signal_];
    }
    return static_cast<std::uint32_t>(d);
}

void HotPlate::place(Cell start, int signal) {
    if (!grid_.contains(start) || signal < 0 || signal >= signalValues(config_)) {
        throw std::invalid_argument("HotPlate::place: start cell or signal out of range");
    }
    position_ = start;
    signal_ = signal;
    optimal_ = distanceToSafety(start);
}

void HotPlate::beginTrial(std::uint64_t seed) {
    TaskRng rng(seed);
    const Cell start{static_cast<int>(rng.below(static_cast<std::uint32_t>(grid_.width()))),
                     static_cast<int>(rng.below(static_cast<std::uint32_t>(grid_.height())))};
    int signal = static_cast<int>(rng.below(static_cast<std::uint32_t>(signalValues(config_))));
    if (config_.swapTrial > 0) signal = trialsBegun_ >= config_.swapTrial ? 1 : 0;  // the hidden safe end
    ++trialsBegun_;
    place(start, signal);
}

void HotPlate::observe(Observation& out) const {
    grid_.writePosition(position_, config_.sensors, out);
    if (config_.signaled) out.setDiscrete(out.discrete.size() - 1, signal_);
}

StepResult HotPlate::act(std::uint32_t action) {
    if (action >= settings_.numActions) throw std::invalid_argument("HotPlate::act: no such action");
    const Move m = config_.dimensions == 1 ? k1DMoves[action] : static_cast<Move>(action);
    position_ = grid_.move(position_, m);
    if (isSafe(position_)) return StepResult{1.0f, true};
    return StepResult{-1.0f, false};
}

}  // namespace verve::tasks
