#include "core/state_representation.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

#include "verve/error.hpp"

namespace verve::core {
namespace {

constexpr float kCutoffWidths = 4.0f;            // activations beyond 4 sigma count as zero

using Lanes = Eigen::Array<float, 8, 1>;

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h * 0xff51afd7ed558ccdULL;
}

}  // namespace

StateRepresentation::StateRepresentation(const AgentDescriptor& desc)
    : discreteCounts_(desc.discreteSensors),
      numContinuous_(static_cast<std::uint32_t>(desc.continuousSensors.size())),
      resolution_(desc.resolution),
      sigma_(2.0f / static_cast<float>(std::max<std::uint32_t>(desc.resolution, 1))),
      // Cells at least 4 sigma wide that tile [-1, 1] exactly, so that the neighbours of a cell
      // hold every RBF within the cutoff, also across the seam of a circular sensor.
      cellsPerDim_(std::max<std::int32_t>(1, static_cast<std::int32_t>(desc.resolution / 4))),
      cellSize_(2.0f / static_cast<float>(cellsPerDim_)),
      keyCount_(1),
      activationSum_(1.0f) {
    for (const auto& s : desc.continuousSensors) circular_.push_back(s.circular);
    for (auto c : discreteCounts_) keyCount_ *= c;
    activationSum_ = std::pow(2.5f, static_cast<float>(numContinuous_));
    coords_.resize(numContinuous_);
    neighbour_.resize(numContinuous_);
    offsets_.resize(numContinuous_);
    candidates_.resize(std::size_t(numContinuous_) * 3);
    candidateCount_.resize(numContinuous_);
    if (desc.allocation == RbfAllocation::Full) allocateFullLattice();
}

std::uint64_t StateRepresentation::discreteKey(const std::int32_t* discrete) const {
    std::uint64_t key = 0;
    for (std::size_t i = 0; i < discreteCounts_.size(); ++i) {
        key = key * discreteCounts_[i] + static_cast<std::uint64_t>(discrete[i]);
    }
    return key;
}

void StateRepresentation::cellCoords(const float* point, std::int32_t* coords) const {
    for (std::uint32_t d = 0; d < numContinuous_; ++d) {
        auto c = static_cast<std::int32_t>(std::floor((point[d] + 1.0f) / cellSize_));
        coords[d] = std::clamp(c, 0, cellsPerDim_ - 1);
    }
}

std::uint64_t StateRepresentation::cellHash(const std::int32_t* coords) const {
    // Distinct cells may collide: that only adds candidates, which the distance test rejects.
    std::uint64_t h = 0x2545f4914f6cdd1dULL;
    for (std::uint32_t d = 0; d < numContinuous_; ++d) h = mix(h, static_cast<std::uint32_t>(coords[d]));
    return h;
}

std::uint32_t StateRepresentation::addFeature(std::uint64_t key, const float* centre) {
    // Everything that allocates comes first; from the first push_back on, nothing can fail.
    reserveRoom(keys_, keys_.size() + 1);
    reserveRoom(centres_, centres_.size() + numContinuous_);
    cellCoords(centre, coords_.data());
    const std::uint64_t hash = cellHash(coords_.data());
    Array& array = arrays_[key];
    Cell* cellPtr = nullptr;
    try {
        cellPtr = &array.cells[hash];
        reserveRoom(cellPtr->features, cellPtr->features.size() + 1);
        reserveRoom(cellPtr->centres, cellPtr->centres.size() + std::size_t(numContinuous_) * kLanes);
    } catch (...) {
        // Undo the empty entries just made (a cell or array that existed before is never empty).
        auto c = array.cells.find(hash);
        if (c != array.cells.end() && c->second.features.empty()) array.cells.erase(c);
        if (array.cells.empty()) arrays_.erase(key);
        throw;
    }
    Cell& cell = *cellPtr;
    const auto index = static_cast<std::uint32_t>(keys_.size());
    keys_.push_back(key);
    centres_.insert(centres_.end(), centre, centre + numContinuous_);
    const std::size_t lane = cell.features.size() % kLanes;
    if (lane == 0) cell.centres.resize(cell.centres.size() + std::size_t(numContinuous_) * kLanes, 0.0f);
    float* block = cell.centres.data() + cell.centres.size() - std::size_t(numContinuous_) * kLanes;
    for (std::uint32_t d = 0; d < numContinuous_; ++d) block[d * kLanes + lane] = centre[d];
    cell.features.push_back(index);
    return index;
}

void StateRepresentation::allocateFullLattice() {
    // AgentDescriptor::validate bounds the lattice (DescriptorLimits::kMaxFullLattice).
    const double perArray = std::pow(static_cast<double>(resolution_), numContinuous_);
    // Lattice centres sit in the middle of resolution equal cells: -1 + (i + 0.5) * sigma.
    std::vector<std::uint32_t> index(numContinuous_, 0);
    std::vector<float> centre(numContinuous_);
    const auto latticeSize = static_cast<std::uint64_t>(perArray);
    for (std::uint64_t key = 0; key < keyCount_; ++key) {
        std::fill(index.begin(), index.end(), 0u);
        for (std::uint64_t n = 0; n < latticeSize; ++n) {
            for (std::uint32_t d = 0; d < numContinuous_; ++d) {
                centre[d] = -1.0f + (static_cast<float>(index[d]) + 0.5f) * sigma_;
            }
            addFeature(key, centre.data());
            for (std::uint32_t d = 0; d < numContinuous_; ++d) {  // odometer
                if (++index[d] < resolution_) break;
                index[d] = 0;
            }
        }
    }
}

std::uint32_t StateRepresentation::add(const std::int32_t* discrete, const float* continuous) {
    return addFeature(discreteKey(discrete), continuous);
}

std::uint32_t StateRepresentation::activate(const std::int32_t* discrete, const float* continuous,
                                            bool allocate, std::vector<ActiveFeature>& out) {
    if (find(discrete, continuous, out) || !allocate) return 0;
    out.push_back(ActiveFeature{addFeature(discreteKey(discrete), continuous), 1.0f});
    return 1;
}

bool StateRepresentation::scanCell(const Cell& c, const float* continuous, std::vector<ActiveFeature>& out) const {
    const float cutoff2 = kCutoffWidths * kCutoffWidths * sigma_ * sigma_;
    const float sigma2 = sigma_ * sigma_;
    const float inv2Sigma2 = 1.0f / (2.0f * sigma2);
    bool nearOne = false;
    std::size_t n = out.size();
    out.resize(n + c.features.size());  // capacity is reused once warmed up
    ActiveFeature* slots = out.data();
    const float* block = c.centres.data();
    for (std::size_t first = 0; first < c.features.size(); first += kLanes) {
        // kLanes RBFs at once: Eigen maps the fixed-size arrays onto SIMD registers.
        Lanes d2 = Lanes::Zero();
        for (std::uint32_t d = 0; d < numContinuous_; ++d, block += kLanes) {
            Lanes diff = continuous[d] - Eigen::Map<const Lanes>(block);
            if (circular_[d]) {  // the shorter way round: -1 and 1 meet
                diff = (diff > 1.0f).select(diff - 2.0f, (diff < -1.0f).select(diff + 2.0f, diff));
            }
            d2 += diff.square();
        }
        const Lanes activation = (d2 * -inv2Sigma2).exp();
        // Branch-free: every candidate is written and kept only within the cutoff
        // (about half are, so a branch would mispredict constantly).
        const std::size_t lanes = std::min<std::size_t>(kLanes, c.features.size() - first);
        for (std::size_t l = 0; l < lanes; ++l) {
            slots[n] = ActiveFeature{c.features[first + l], activation[l]};
            n += d2[l] < cutoff2;
            nearOne |= d2[l] < sigma2;
        }
    }
    out.resize(n);
    return nearOne;
}

bool StateRepresentation::find(const std::int32_t* discrete, const float* continuous,
                               std::vector<ActiveFeature>& out) const {
    out.clear();
    auto arrayIt = arrays_.find(discreteKey(discrete));
    if (arrayIt == arrays_.end()) return false;
    const auto& cells = arrayIt->second.cells;

    // Distinct neighbouring cell coordinates per dimension (wrapping on circular sensors).
    cellCoords(continuous, coords_.data());
    std::size_t neighbours = 1;
    for (std::uint32_t d = 0; d < numContinuous_; ++d) {
        std::uint8_t n = 0;
        for (int off = -1; off <= 1; ++off) {
            std::int32_t c = coords_[d] + off;
            if (circular_[d]) c = (c % cellsPerDim_ + cellsPerDim_) % cellsPerDim_;
            else if (c < 0 || c >= cellsPerDim_) continue;
            bool seen = false;
            for (std::uint8_t k = 0; k < n; ++k) seen |= candidates_[d * 3 + k] == c;
            if (!seen) candidates_[d * 3 + n++] = c;
        }
        candidateCount_[d] = n;
        offsets_[d] = 0;
        neighbours *= n;
    }

    bool nearOne = false;
    if (cells.size() <= neighbours) {
        // A coarse grid (low resolution, many sensors): the array has no more cells than the
        // neighbourhood, so reading them all costs no more and needs no hashing.
        for (const auto& entry : cells) nearOne |= scanCell(entry.second, continuous, out);
        return nearOne;
    }
    visited_.clear();
    while (true) {
        for (std::uint32_t d = 0; d < numContinuous_; ++d) neighbour_[d] = candidates_[d * 3 + offsets_[d]];
        const std::uint64_t hash = cellHash(neighbour_.data());
        auto cell = cells.find(hash);
        // Two neighbour cells whose hashes collide share one list: visit it once.
        if (cell != cells.end() && std::find(visited_.begin(), visited_.end(), hash) == visited_.end()) {
            visited_.push_back(hash);
            nearOne |= scanCell(cell->second, continuous, out);
        }
        std::uint32_t d = 0;
        for (; d < numContinuous_; ++d) {  // odometer over the neighbour cells
            if (++offsets_[d] < candidateCount_[d]) break;
            offsets_[d] = 0;
        }
        if (d == numContinuous_) break;
    }
    return nearOne;
}

}  // namespace verve::core
