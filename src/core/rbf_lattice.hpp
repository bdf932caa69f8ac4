// One RBF lattice (thesis chapter 4, "RBF State Representation") over some continuous sensors: the
// whole state representation of an agent with a few sensors, one of its groups with many
// (core/state_representation.hpp).
//
// One RBF array per combination of discrete sensor values; within an array, Gaussian RBFs of width
// sigma = 2 / resolution over the lattice's continuous sensors in [-1, 1]. With no continuous
// sensors an array is a single feature that is fully active for its combination. RBFs are found
// through a uniform grid of cells 4 sigma wide, so activating an observation touches only the cells
// around it, never all RBFs ever made. Feature indices are given by the caller: the lattices of one
// representation number their RBFs in one sequence.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/active_feature.hpp"
#include "core/kernels.hpp"
#include "core/weight_table.hpp"
#include "verve/agent_descriptor.hpp"

namespace verve::core {

// A lookup's scratch, and its measure of whether block boxes pay (RbfLattice::find). A
// representation keeps one for its own lookups; a batch that looks up the bodies of one brain on
// several threads at once gives each worker its own (core/shared_step.hpp). Either way a lookup
// finds the same features in the same order: the measure only chooses how cells are read.
struct LookupScratch {
    static constexpr std::uint32_t kMaxDims = DescriptorLimits::kMaxLatticeSensors;
    std::uint32_t blocksTested = 0, blocksKept = 0;
    std::uint32_t wholeLookupsLeft = 0;
    std::array<std::int32_t, kMaxDims> coords{}, neighbour{}, offsets{};
    std::array<std::int32_t, 3 * kMaxDims> candidates{};  // per dimension up to 3 distinct cell coordinates
    std::array<std::uint8_t, kMaxDims> candidateCount{};
    std::vector<std::uint64_t> visited;  // cell hashes already read this activation
    std::uint64_t uncovered = 0;  // StateRepresentation::find: bit g set when group g has no RBF within one width
};

class RbfLattice {
public:
    // `circular`: per continuous sensor of this lattice, 1 when it wraps.
    RbfLattice(const std::vector<std::uint32_t>& discreteCounts, const std::vector<std::uint8_t>& circular,
               std::uint32_t resolution);

    // A new RBF is made in two steps, so that several lattices can add one each or none: prepare
    // allocates (strong guarantee: if it throws, the lattice is as it was), then either commit,
    // which cannot fail, or cancel.
    struct Slot {
        void* cell = nullptr;
        std::uint64_t key = 0, hash = 0;
    };
    Slot prepare(std::uint64_t key, const float* centre);
    void commit(const Slot& slot, const float* centre, std::uint32_t index) noexcept;
    void cancel(const Slot& slot) noexcept;
    std::uint64_t discreteKey(const std::int32_t* discrete) const;
    // Room for lookups once there are `features` RBFs: find() then allocates nothing, given an
    // output vector with foundCapacity(features) room (the scan writes whole lanes, then trims).
    // A lookup visits at most 3^n cells, each once, and never more cells than RBFs.
    void reserve(std::uint32_t features) { reserve(own_, features); }
    // The same for a scratch of the caller's.
    void reserve(LookupScratch& scratch, std::uint32_t features) const {
        if (!exactCellKeys_) reserveRoom(scratch.visited,  // only hashed keys use it; the minimum fits in 32 bits
                                         static_cast<std::size_t>(std::min<std::uint64_t>(features, maxNeighbours_)));
    }
    static std::size_t foundCapacity(std::uint32_t features) { return std::size_t(features) + kScanLanes; }
    // Appends the active features of an observation whose continuous values (this lattice's
    // sensors) are already in [-1, 1], without allocating; returns whether some RBF lies within one
    // width. `ahead`: a batch's next agent, asked for as the scan goes (prefetch.hpp).
    bool find(const std::int32_t* discrete, const float* continuous, std::vector<ActiveFeature>& out,
              PrefetchQueue* ahead = nullptr) const {
        return find(discrete, continuous, out, own_, ahead);
    }
    // The same with the caller's scratch (reserved for this lattice): lookups with scratches of
    // their own may run at once on several threads (nothing else may change it then).
    bool find(const std::int32_t* discrete, const float* continuous, std::vector<ActiveFeature>& out,
              LookupScratch& scratch, PrefetchQueue* ahead = nullptr) const;

    std::uint32_t featureCount() const { return featureCount_; }
    std::uint32_t numContinuous() const { return numContinuous_; }
    const std::uint8_t* circular() const { return circular_.data(); }  // per continuous sensor: 1 when it wraps
    std::uint64_t keyCount() const { return keyCount_; }
    // Whether the next lookup reads cells whole rather than through their block boxes (judgeBoxes).
    bool readsCellsWhole() const { return own_.wholeLookupsLeft > 0; }
    // Calls f(index, discrete key, centre) for every feature (the centre has numContinuous values).
    // Not for the hot path: the grid cells hold the only copy of a centre, so this walks all of them.
    template <typename F>
    void forEachFeature(F&& f) const {
        std::array<float, kMaxDims> centre{};
        for (const auto& [key, array] : arrays_) {
            for (const auto& entry : array.cells) {
                const Cell& cell = entry.second;
                for (std::size_t i = 0; i < cell.features.size(); ++i) {
                    const float* block = cell.centres.data() + (i / kScanLanes) * numContinuous_ * kScanLanes;
                    for (std::uint32_t d = 0; d < numContinuous_; ++d) centre[d] = block[d * kScanLanes + i % kScanLanes];
                    f(cell.features[i], key, centre.data());
                }
            }
        }
    }
    // A batch's staged prefetch of the next lookup (Agent::Impl::prefetch), for a representation
    // of one array of one cell (a dynamic agent without discrete sensors below resolution 16, or
    // of one or two sensors up to resolution 1024 or 32: rbf_lattice.cpp, kOneCellRbfs):
    // stage 0 asks for the array, 1 for its cell, 2 for the cell's centres; each stage reads only
    // what the one before asked for. Other representations ask for nothing.
    static constexpr unsigned kPrefetchStages = 3;
    void prefetchLookup(unsigned stage) const noexcept;
    // The same batch's PrefetchQueue: the centres of such a representation's cell.
    void addArraysTo(PrefetchQueue& q) const noexcept;

    // Divides the learning rates: the expected activation sum of a lattice of RBFs,
    // sqrt(2 pi) ~ 2.5 per continuous dimension, and 1 when all sensors are discrete.
    float activationSum() const { return activationSum_; }

    // Adds a feature numbered `index` (centre has numContinuous values, already validated).
    void addFeature(std::uint64_t key, const float* centre, std::uint32_t index);
    // Makes the whole resolution^n lattice of every discrete combination, numbered from `next`
    // on (which it advances), then finishes it.
    void allocateFullLattice(std::uint32_t& next);
    // Once a full lattice is complete (made, or restored from a save): puts each cell's RBFs in
    // Morton order of their lattice indices and drops spare capacity. No RBF may be added after.
    void finishLattice();

private:
    // A cell keeps copies of its RBFs' centres next to their indices, in blocks of kScanLanes RBFs
    // stored dimension by dimension ([block][dimension][lane]): the distance loop then runs
    // across kScanLanes RBFs at once in SIMD registers.
    // A cell also keeps the bounding box of its centres, and one per block: a cell or a block
    // whose box lies beyond the cutoff is skipped unread (in 4-D most of the 3^4 neighbour cells'
    // RBFs are out of reach). A full lattice is stored in Morton order within each cell, so that
    // a block is a small box (2x2x2x1 lattice points in 4-D) and the blocks read are mostly kept.
    struct Cell {
        std::vector<std::uint32_t> features;
        // Set while features[i] == firstFeature + i (a dynamic agent with one array and one cell
        // numbers its RBFs in the order they were made): the scan then counts the indices instead
        // of reading them, 4 bytes per RBF of memory traffic fewer.
        bool consecutive = true;
        std::uint32_t firstFeature = 0;
        std::vector<float> centres;      // blocks of numContinuous_ * kScanLanes floats
        std::vector<float> bounds;       // per dimension: lowest, highest centre
        std::vector<float> blockBounds;  // the same per block, in groups of kScanLanes blocks (Kernels::boxesWithin)
    };
    struct Array {
        std::unordered_map<std::uint64_t, Cell> cells;
    };

    // Appends the RBFs of one cell within the cutoff; returns whether one lies within a width.
    // Without `boxes`, a cell is read whole, never through its block boxes (same result). An array's
    // only cell (`alone`) skips the test of its own box: it holds every RBF the agent made along
    // its way, so the test nearly always passes, and its bounds would be one more cache miss.
    bool scanCell(const Cell& c, const ScanParams& params, bool boxes, bool alone, std::vector<ActiveFeature>& out,
                  LookupScratch& scratch) const;
    // After a lookup that tested block boxes: once enough blocks were tested, and nearly all of
    // them passed, the next kWholeLookups lookups read their cells whole (the scratch's counters).
    void judgeBoxes(LookupScratch& scratch) const;
    // Squared distance from a point to a bounding box (per dimension: lowest, highest), the
    // shorter way on circular sensors; and the same to the box's farthest corner.
    float boxDistance2(const float* bounds, const float* point) const;
    float farthestDistance2(const float* bounds, const float* point) const;
    // A cell of up to 16 blocks is always read whole, and keeps no block boxes: testing them
    // would cost about what it saves.
    static constexpr std::size_t kReadWhole = 16 * kScanLanes;
    static std::size_t groupsFor(std::size_t rbfs) { return (rbfs + kScanLanes * kScanLanes - 1) / (kScanLanes * kScanLanes); }
    std::size_t boundsGroupFloats() const { return std::size_t(numContinuous_) * 2 * kScanLanes; }
    // Widens a box (lowest of dimension d at lo[d * step], highest at lo[d * step + hiOffset]) to
    // a centre (dimension d at centre[d * centreStep]).
    void updateBounds(float* lo, std::size_t hiOffset, std::size_t step, const float* centre, std::size_t centreStep,
                      bool first) const;
    void updateBlockBounds(Cell& c, std::size_t rbf) const;  // to the cell's RBF number rbf
    void rebuildBlockBounds(Cell& c) const;
    // The array of a representation without discrete sensors, and its cell when it has one only
    // (what the batch's prefetches follow); null otherwise.
    const Array* onlyArray() const noexcept;
    const Cell* onlyCell() const noexcept;
    void cellCoords(const float* point, std::int32_t* coords) const;
    // Fills the scratch's candidates (up to 3 distinct cell coordinates per dimension around the
    // point) and resets its odometer offsets; returns the number of neighbour cells.
    std::size_t neighbourCandidates(const float* point, LookupScratch& scratch) const;
    std::uint64_t cellHash(const std::int32_t* coords) const;

    std::vector<std::uint32_t> discreteCounts_;
    // Per continuous sensor, 1 when -1 and 1 meet. Inline (kMaxSensors), like the neighbour
    // scratch below: small blocks of their own would each be a cache miss of a crowd's update.
    static constexpr std::uint32_t kMaxDims = LookupScratch::kMaxDims;
    std::array<std::uint8_t, kMaxDims> circular_{};
    std::uint32_t numContinuous_;
    std::uint32_t resolution_;
    float sigma_;
    std::int32_t cellsPerDim_;
    float cellSize_;
    std::uint64_t maxNeighbours_;  // 3^numContinuous, saturated
    bool exactCellKeys_ = false;   // a cell's key is its coordinates (else a hash that may collide)
    std::uint64_t keyCount_;
    float activationSum_;
    const Kernels* kernels_;  // chosen for this CPU (kernels.hpp)

    std::unordered_map<std::uint64_t, Array> arrays_;
    std::uint32_t featureCount_ = 0;

    // Whether block boxes pay, measured on the lookups themselves. Reading a block's box costs
    // 2 floats per dimension, reading the block (dims + 1) * kScanLanes: the boxes save bytes only
    // when they skip more than dims / (4 (dims + 1)) of the blocks tested (a fifth in 4-D), and
    // compute only when they skip more. Where the RBFs lie along the paths an agent took (a
    // dynamic agent, e.g. the cart-pole shape's 676 RBFs in one cell) nearly every block passes,
    // and reading the boxes is a quarter more memory traffic for nothing; in a dense lattice
    // most blocks are skipped. Cells are then read whole for kWholeLookups lookups, then the
    // boxes are measured again. Either way a lookup finds the same features, in the same order.
    static constexpr std::uint32_t kJudgeBlocks = 256;   // blocks tested before a verdict
    static constexpr std::uint32_t kWholeLookups = 128;   // lookups read whole after a verdict

    // The scratch of the representation's own lookups (no allocation once warmed up). Mutable:
    // lookups are logically const, and one agent is used by one thread at a time. Last: a lookup
    // in an array of one cell reads none of it, and the members above then share fewer cache lines.
    mutable LookupScratch own_;
};

}  // namespace verve::core
