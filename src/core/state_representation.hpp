// The RBF state representation (thesis chapter 4, "RBF State Representation"): one RBF lattice
// over the continuous sensors (core/rbf_lattice.hpp), or, for many sensors, one lattice per group
// of sensors whose features are summed (core/sensor_groups.hpp). The groups number their RBFs in
// one sequence, so the learner sees one list of features either way.
#pragma once
#include <cstdint>
#include <vector>

#include "core/rbf_lattice.hpp"

namespace verve::core {

class StateRepresentation {
public:
    explicit StateRepresentation(const AgentDescriptor& desc);

    // Active features of an observation whose continuous values are already in [-1, 1]; returns
    // whether every group has an RBF within one width (the scratch records which have none).
    // `ahead`: a batch's next agent, asked for as the scan goes (prefetch.hpp).
    bool find(const std::int32_t* discrete, const float* continuous, std::vector<ActiveFeature>& out,
              PrefetchQueue* ahead = nullptr) const {
        return find(discrete, continuous, out, own_, ahead);
    }
    // The same with the caller's scratch (reserved for this representation): lookups with
    // scratches of their own may run at once on several threads (nothing else may change it then).
    bool find(const std::int32_t* discrete, const float* continuous, std::vector<ActiveFeature>& out,
              LookupScratch& scratch, PrefetchQueue* ahead = nullptr) const;
    // How many RBFs the last find() on the representation's own scratch found missing (one per
    // group without an RBF within one width), and adding them: each is centred on the
    // observation and appended to `out` with activation 1. Strong guarantee: if an allocation
    // fails, it throws and the representation is as it was. Returns the number added.
    std::uint32_t missing() const { return static_cast<std::uint32_t>(__builtin_popcountll(own_.uncovered)); }
    std::uint32_t addMissing(const std::int32_t* discrete, const float* continuous, std::vector<ActiveFeature>& out);
    // find(), then with `allocate` addMissing(): returns the number of RBFs added.
    std::uint32_t activate(const std::int32_t* discrete, const float* continuous, bool allocate,
                           std::vector<ActiveFeature>& out);

    // Room for lookups once there are `features` RBFs: find() then allocates nothing, given an
    // output vector with foundCapacity(features) room.
    void reserve(std::uint32_t features) { reserve(own_, features); }
    void reserve(LookupScratch& scratch, std::uint32_t features) const {
        for (const auto& g : groups_) g.lattice.reserve(scratch, features);
    }
    static std::size_t foundCapacity(std::uint32_t features) { return RbfLattice::foundCapacity(features); }

    std::uint32_t featureCount() const { return featureCount_; }
    std::size_t groupCount() const { return groups_.size(); }
    std::uint32_t numContinuous() const { return numContinuous_; }
    const std::uint8_t* circular() const { return circular_.data(); }  // per continuous sensor: 1 when it wraps
    // Saved features' keys lie below this: group * (discrete combinations) + discrete key.
    std::uint64_t keyCount() const { return keyCount_ * groups_.size(); }
    bool readsCellsWhole() const { return own_.wholeLookupsLeft > 0; }
    // Every feature's saved key and centre (numContinuous values; 0 for sensors outside its
    // group), by feature index. Not for the hot path.
    void features(std::vector<std::uint64_t>& keys, std::vector<float>& centres) const;
    // A batch's staged prefetch of the next lookup (RbfLattice::prefetchLookup), for up to four
    // lattices (one, a small one and its fine twin, or a lattice of 3-4 sensors and the pairs
    // beside it: core/lattice_layout.hpp). Sensor groups' many small lattices are left to the
    // hardware: their arrays would crowd out the traces.
    static constexpr unsigned kPrefetchStages = RbfLattice::kPrefetchStages;
    static constexpr std::size_t kPrefetchedLattices = 4;
    void prefetchLookup(unsigned stage) const noexcept {
        if (groups_.size() > kPrefetchedLattices) return;
        for (const Group& group : groups_) group.lattice.prefetchLookup(stage);
    }
    void addArraysTo(PrefetchQueue& q) const noexcept {
        if (groups_.size() > kPrefetchedLattices) return;
        for (const Group& group : groups_) group.lattice.addArraysTo(q);
    }
    // Divides the learning rates: the expected activation sum, summed over the lattices (one
    // beside the agent's groups counts its share of its own: core/lattice_layout.hpp).
    float activationSum() const { return activationSum_; }
    // Lattice k's part of that sum, and which lattice made feature f (core/group_rates.hpp).
    float latticeSum(std::size_t k) const { return groups_[k].share * groups_[k].lattice.activationSum(); }
    std::uint8_t latticeOf(std::uint32_t feature) const { return latticeOf_[feature]; }

    // Restores a saved feature (a key below keyCount(), a centre of numContinuous values, both
    // validated) as the next feature.
    void addFeature(std::uint64_t key, const float* centre);
    // Once full lattices are complete (made, or restored from a save): RbfLattice::finishLattice.
    void finishLattice();

private:
    struct Group {
        std::vector<std::uint32_t> sensors;  // continuous sensor indices, lowest first
        bool all = false;                    // every continuous sensor in order: no gather needed
        RbfLattice lattice;
        float share = 1.0f;                  // of its expected activation sum in the rates' divisor
    };
    // The group's sensor values of an observation: the observation itself when the group holds
    // every sensor, else gathered into `buffer`.
    const float* point(const Group& g, const float* continuous, float* buffer) const;

    std::vector<Group> groups_;
    std::array<std::uint8_t, DescriptorLimits::kMaxSensors> circular_{};  // every sensor; a lattice spans fewer
    std::uint32_t numContinuous_ = 0;
    std::uint64_t keyCount_ = 1;  // discrete combinations
    std::uint32_t featureCount_ = 0;
    std::vector<std::uint8_t> latticeOf_;  // per feature (at most kMaxSensorGroups lattices)
    float activationSum_ = 0.0f;
    mutable LookupScratch own_;
};

}  // namespace verve::core
