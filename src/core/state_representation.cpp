#include "core/state_representation.hpp"

#include <array>

#include "core/lattice_layout.hpp"
#include "core/sensor_groups.hpp"
#include "verve/error.hpp"

namespace verve::core {
namespace {

std::vector<std::uint8_t> circularOf(const AgentDescriptor& desc, const std::vector<std::uint32_t>& sensors) {
    std::vector<std::uint8_t> circular;
    for (auto i : sensors) circular.push_back(desc.continuousSensors[i].circular ? 1 : 0);
    return circular;
}

}  // namespace

StateRepresentation::StateRepresentation(const AgentDescriptor& desc)
    : numContinuous_(static_cast<std::uint32_t>(desc.continuousSensors.size())) {
    if (numContinuous_ > DescriptorLimits::kMaxSensors) throw Error(ErrorCode::InvalidArgument, "too many continuous sensors");
    for (std::uint32_t d = 0; d < numContinuous_; ++d) circular_[d] = desc.continuousSensors[d].circular ? 1 : 0;
    for (auto c : desc.discreteSensors) keyCount_ *= c;
    const auto specs = lattices(desc);
    groups_.reserve(specs.size());
    for (const auto& spec : specs) {
        auto sensors = groupSensors(spec.sensors);
        const bool all = sensors.size() == numContinuous_;
        auto circular = circularOf(desc, sensors);
        groups_.push_back(Group{std::move(sensors), all, RbfLattice(desc.discreteSensors, circular, spec.resolution), spec.share});
        // A lattice beside the agent's groups counts its share (core/lattice_layout.hpp).
        activationSum_ += latticeSum(groups_.size() - 1);
    }
    if (desc.allocation == RbfAllocation::Full) {
        for (std::size_t i = 0; i < groups_.size(); ++i) {
            groups_[i].lattice.allocateFullLattice(featureCount_);
            latticeOf_.resize(featureCount_, static_cast<std::uint8_t>(i));
        }
    }
}

const float* StateRepresentation::point(const Group& g, const float* continuous, float* buffer) const {
    if (g.all) return continuous;
    for (std::size_t d = 0; d < g.sensors.size(); ++d) buffer[d] = continuous[g.sensors[d]];
    return buffer;
}

bool StateRepresentation::find(const std::int32_t* discrete, const float* continuous, std::vector<ActiveFeature>& out,
                               LookupScratch& scratch, PrefetchQueue* ahead) const {
    out.clear();
    std::array<float, LookupScratch::kMaxDims> buffer;
    std::uint64_t uncovered = 0;
    for (std::size_t i = 0; i < groups_.size(); ++i) {
        const Group& g = groups_[i];
        if (!g.lattice.find(discrete, point(g, continuous, buffer.data()), out, scratch, ahead)) {
            uncovered |= std::uint64_t(1) << i;
        }
    }
    scratch.uncovered = uncovered;
    return uncovered == 0;
}

std::uint32_t StateRepresentation::addMissing(const std::int32_t* discrete, const float* continuous,
                                              std::vector<ActiveFeature>& out) {
    // Every group's room first; only once all have it does any RBF appear (strong guarantee).
    std::array<float, LookupScratch::kMaxDims> buffer;
    std::array<RbfLattice::Slot, DescriptorLimits::kMaxSensorGroups> slots;
    const std::uint64_t key = groups_[0].lattice.discreteKey(discrete);
    std::size_t prepared = 0;
    try {
        for (; prepared < groups_.size(); ++prepared) {
            if ((own_.uncovered >> prepared) & 1u) {
                const Group& g = groups_[prepared];
                slots[prepared] = groups_[prepared].lattice.prepare(key, point(g, continuous, buffer.data()));
            }
        }
        reserveRoom(out, out.size() + missing());
        reserveRoom(latticeOf_, std::size_t(featureCount_) + missing());
    } catch (...) {
        for (std::size_t i = 0; i < prepared; ++i) {
            if ((own_.uncovered >> i) & 1u) groups_[i].lattice.cancel(slots[i]);
        }
        throw;
    }
    std::uint32_t added = 0;
    for (std::size_t i = 0; i < groups_.size(); ++i) {
        if (!((own_.uncovered >> i) & 1u)) continue;
        const Group& g = groups_[i];
        groups_[i].lattice.commit(slots[i], point(g, continuous, buffer.data()), featureCount_);
        latticeOf_.push_back(static_cast<std::uint8_t>(i));
        out.push_back(ActiveFeature{featureCount_++, 1.0f});
        ++added;
    }
    own_.uncovered = 0;
    return added;
}

std::uint32_t StateRepresentation::activate(const std::int32_t* discrete, const float* continuous, bool allocate,
                                            std::vector<ActiveFeature>& out) {
    if (find(discrete, continuous, out) || !allocate) return 0;
    return addMissing(discrete, continuous, out);
}

void StateRepresentation::features(std::vector<std::uint64_t>& keys, std::vector<float>& centres) const {
    keys.assign(featureCount_, 0);
    centres.assign(std::size_t(featureCount_) * numContinuous_, 0.0f);
    for (std::size_t i = 0; i < groups_.size(); ++i) {
        const Group& g = groups_[i];
        g.lattice.forEachFeature([&](std::uint32_t f, std::uint64_t key, const float* centre) {
            keys[f] = i * keyCount_ + key;
            for (std::size_t d = 0; d < g.sensors.size(); ++d) centres[std::size_t(f) * numContinuous_ + g.sensors[d]] = centre[d];
        });
    }
}

void StateRepresentation::addFeature(std::uint64_t key, const float* centre) {
    Group& g = groups_[key / keyCount_];
    std::array<float, LookupScratch::kMaxDims> buffer;
    // Before the lattice changes; geometric, as a restore adds every feature one by one.
    reserveRoom(latticeOf_, std::size_t(featureCount_) + 1);
    g.lattice.addFeature(key % keyCount_, point(g, centre, buffer.data()), featureCount_);
    latticeOf_.push_back(static_cast<std::uint8_t>(key / keyCount_));
    ++featureCount_;
}

void StateRepresentation::finishLattice() {
    for (auto& g : groups_) g.lattice.finishLattice();
}

}  // namespace verve::core
