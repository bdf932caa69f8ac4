#include "core/rbf_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/prefetch.hpp"
#include "verve/error.hpp"

namespace verve::core {
namespace {

constexpr float kCutoffWidths = 4.0f;            // activations beyond 4 sigma count as zero

// Cells at least 4 sigma wide that tile [-1, 1] exactly, so that the neighbours of a cell hold
// every RBF within the cutoff, also across the seam of a circular sensor. One cell holds the whole
// array, read as one stream whose blocks' boxes do the skipping, when a lookup would read (nearly)
// all cells anyway (3 or fewer per dimension), and when the whole lattice is small
// (kOneCellRbfs): a lookup of one or two sensors at resolution 20 would otherwise hash its way
// through 9 of 25 scattered cells, each a cache miss in a crowd, to scan what one stream of at
// most a few hundred centres holds.
constexpr double kOneCellRbfs = 1024;

std::int32_t cellsPerDim(std::uint32_t resolution, std::size_t dims) {
    if (resolution / 4 <= 3 || std::pow(double(resolution), double(dims)) <= kOneCellRbfs) return 1;
    return static_cast<std::int32_t>(resolution / 4);
}

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h * 0xff51afd7ed558ccdULL;
}

}  // namespace

RbfLattice::RbfLattice(const std::vector<std::uint32_t>& discreteCounts, const std::vector<std::uint8_t>& circular,
                       std::uint32_t resolution)
    : discreteCounts_(discreteCounts),
      numContinuous_(static_cast<std::uint32_t>(circular.size())),
      resolution_(resolution),
      sigma_(2.0f / static_cast<float>(std::max<std::uint32_t>(resolution, 1))),
      cellsPerDim_(cellsPerDim(resolution, circular.size())),
      cellSize_(2.0f / static_cast<float>(cellsPerDim_)),
      maxNeighbours_(1),
      keyCount_(1),
      activationSum_(1.0f),
      kernels_(&kernels()) {
    if (numContinuous_ > kMaxDims) throw Error(ErrorCode::InvalidArgument, "too many continuous sensors in one lattice");
    for (std::uint32_t d = 0; d < numContinuous_; ++d) circular_[d] = circular[d];
    for (auto c : discreteCounts_) keyCount_ *= c;
    for (std::uint32_t d = 0; d < numContinuous_ && maxNeighbours_ < (1ULL << 40); ++d) maxNeighbours_ *= 3;
    double cells = 1.0;
    for (std::uint32_t d = 0; d < numContinuous_; ++d) cells *= cellsPerDim_;
    exactCellKeys_ = cells < 0x1p63;
    activationSum_ = std::pow(2.5f, static_cast<float>(numContinuous_));
}

std::uint64_t RbfLattice::discreteKey(const std::int32_t* discrete) const {
    std::uint64_t key = 0;
    for (std::size_t i = 0; i < discreteCounts_.size(); ++i) {
        key = key * discreteCounts_[i] + static_cast<std::uint64_t>(discrete[i]);
    }
    return key;
}

void RbfLattice::cellCoords(const float* point, std::int32_t* coords) const {
    for (std::uint32_t d = 0; d < numContinuous_; ++d) {
        auto c = static_cast<std::int32_t>(std::floor((point[d] + 1.0f) / cellSize_));
        coords[d] = std::clamp(c, 0, cellsPerDim_ - 1);
    }
}

std::uint64_t RbfLattice::cellHash(const std::int32_t* coords) const {
    if (exactCellKeys_) {  // the coordinates in mixed radix: no two cells share a key
        std::uint64_t key = 0;
        for (std::uint32_t d = numContinuous_; d-- > 0;) key = key * std::uint64_t(cellsPerDim_) + std::uint32_t(coords[d]);
        return key;
    }
    // Distinct cells may collide: that only adds candidates, which the distance test rejects.
    std::uint64_t h = 0x2545f4914f6cdd1dULL;
    for (std::uint32_t d = 0; d < numContinuous_; ++d) h = mix(h, static_cast<std::uint32_t>(coords[d]));
    return h;
}

RbfLattice::Slot RbfLattice::prepare(std::uint64_t key, const float* centre) {
    std::array<std::int32_t, kMaxDims> coords{};
    cellCoords(centre, coords.data());
    Slot slot;
    slot.key = key;
    slot.hash = cellHash(coords.data());
    Array& array = arrays_[key];
    try {
        Cell& cell = array.cells[slot.hash];
        slot.cell = &cell;  // stays put: an unordered_map's nodes never move
        reserveRoom(cell.features, cell.features.size() + 1);
        reserveRoom(cell.centres, cell.centres.size() + std::size_t(numContinuous_) * kScanLanes);
        if (cell.bounds.empty()) cell.bounds.assign(std::size_t(numContinuous_) * 2, 0.0f);
        const std::size_t count = cell.features.size() + 1;
        if (count > kReadWhole) reserveRoom(cell.blockBounds, groupsFor(count) * boundsGroupFloats());
    } catch (...) {
        cancel(slot);
        throw;
    }
    return slot;
}

void RbfLattice::cancel(const Slot& slot) noexcept {
    // Undo the empty entries prepare made (a cell or array that existed before is never empty).
    auto a = arrays_.find(slot.key);
    if (a == arrays_.end()) return;
    auto c = a->second.cells.find(slot.hash);
    if (c != a->second.cells.end() && c->second.features.empty()) a->second.cells.erase(c);
    if (a->second.cells.empty()) arrays_.erase(a);
}

void RbfLattice::addFeature(std::uint64_t key, const float* centre, std::uint32_t index) {
    commit(prepare(key, centre), centre, index);
}

void RbfLattice::commit(const Slot& slot, const float* centre, std::uint32_t index) noexcept {
    // Within the capacity prepare reserved: nothing here allocates.
    Cell& cell = *static_cast<Cell*>(slot.cell);
    ++featureCount_;
    const std::size_t lane = cell.features.size() % kScanLanes;
    if (lane == 0) cell.centres.resize(cell.centres.size() + std::size_t(numContinuous_) * kScanLanes, 0.0f);
    float* block = cell.centres.data() + cell.centres.size() - std::size_t(numContinuous_) * kScanLanes;
    for (std::uint32_t d = 0; d < numContinuous_; ++d) block[d * kScanLanes + lane] = centre[d];
    updateBounds(cell.bounds.data(), 1, 2, centre, 1, cell.features.empty());
    if (cell.features.empty()) cell.firstFeature = index;
    cell.consecutive = cell.features.empty() || (cell.consecutive && index == cell.features.back() + 1);
    cell.features.push_back(index);
    const std::size_t count = cell.features.size();
    if (count > kReadWhole) {
        if (cell.blockBounds.empty()) {
            rebuildBlockBounds(cell);
        } else {
            cell.blockBounds.resize(groupsFor(count) * boundsGroupFloats(), 0.0f);
            updateBlockBounds(cell, count - 1);
        }
    }
}

void RbfLattice::updateBounds(float* lo, std::size_t hiOffset, std::size_t step, const float* centre,
                                       std::size_t centreStep, bool first) const {
    // Offsets, not a second pointer: with no continuous sensors the bounds are empty (a null
    // data()), and nothing may be added to a null pointer even when nothing is then read.
    for (std::uint32_t d = 0; d < numContinuous_; ++d) {
        const float x = centre[d * centreStep];
        float& low = lo[d * step];
        float& high = lo[d * step + hiOffset];
        low = first ? x : std::min(low, x);
        high = first ? x : std::max(high, x);
    }
}

void RbfLattice::updateBlockBounds(Cell& c, std::size_t rbf) const {
    const std::size_t block = rbf / kScanLanes;
    float* lo = c.blockBounds.data() + (block / kScanLanes) * boundsGroupFloats() + block % kScanLanes;
    const float* centre = c.centres.data() + block * numContinuous_ * kScanLanes + rbf % kScanLanes;
    updateBounds(lo, kScanLanes, 2 * kScanLanes, centre, kScanLanes, rbf % kScanLanes == 0);
}

void RbfLattice::rebuildBlockBounds(Cell& c) const {
    const std::size_t count = c.features.size();
    if (count <= kReadWhole) {
        c.blockBounds.clear();
        return;
    }
    c.blockBounds.assign(groupsFor(count) * boundsGroupFloats(), 0.0f);
    for (std::size_t i = 0; i < count; ++i) updateBlockBounds(c, i);
}

void RbfLattice::allocateFullLattice(std::uint32_t& next) {
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
            addFeature(key, centre.data(), next++);
            for (std::uint32_t d = 0; d < numContinuous_; ++d) {  // odometer
                if (++index[d] < resolution_) break;
                index[d] = 0;
            }
        }
    }
    finishLattice();
}

void RbfLattice::finishLattice() {
    // Morton order: the lattice indices' bits interleaved, lowest bits first, so that any 2^k
    // consecutive RBFs of a cell form a box about 2 lattice points wide in k dimensions.
    const std::uint32_t bits = std::max<std::uint32_t>(1, 64 / std::max<std::uint32_t>(numContinuous_, 1));
    std::vector<std::pair<std::uint64_t, std::uint32_t>> order;
    std::vector<std::uint32_t> features;
    std::vector<float> centres;
    for (auto& [key, array] : arrays_) {
        for (auto& entry : array.cells) {
            Cell& cell = entry.second;
            const std::size_t count = cell.features.size();
            order.clear();
            for (std::size_t i = 0; i < count; ++i) {
                const float* block = cell.centres.data() + (i / kScanLanes) * numContinuous_ * kScanLanes;
                std::uint64_t code = 0;
                for (std::uint32_t d = 0; d < numContinuous_; ++d) {
                    const float local = (block[d * kScanLanes + i % kScanLanes] - cell.bounds[2 * d]) / sigma_;
                    const auto q = static_cast<std::uint64_t>(std::lround(local));
                    for (std::uint32_t b = 0; b < bits; ++b) code |= ((q >> b) & 1u) << (b * numContinuous_ + d);
                }
                order.emplace_back(code, static_cast<std::uint32_t>(i));
            }
            std::sort(order.begin(), order.end());
            features.assign(cell.features.begin(), cell.features.end());
            centres.assign(cell.centres.begin(), cell.centres.end());
            for (std::size_t i = 0; i < count; ++i) {
                const std::size_t from = order[i].second;
                cell.features[i] = features[from];
                const float* src = centres.data() + (from / kScanLanes) * numContinuous_ * kScanLanes;
                float* dst = cell.centres.data() + (i / kScanLanes) * numContinuous_ * kScanLanes;
                for (std::uint32_t d = 0; d < numContinuous_; ++d) {
                    dst[d * kScanLanes + i % kScanLanes] = src[d * kScanLanes + from % kScanLanes];
                }
            }
            rebuildBlockBounds(cell);
            cell.firstFeature = count > 0 ? cell.features[0] : 0;
            cell.consecutive = true;
            for (std::size_t i = 1; i < count; ++i) cell.consecutive = cell.consecutive && cell.features[i] == cell.firstFeature + i;
            // The lattice is complete: no cell grows again, so none keeps spare capacity.
            cell.features.shrink_to_fit();
            cell.centres.shrink_to_fit();
            cell.blockBounds.shrink_to_fit();
        }
    }
}

float RbfLattice::boxDistance2(const float* bounds, const float* point) const {
    float sum = 0.0f;
    for (std::uint32_t d = 0; d < numContinuous_; ++d) {
        const float lo = bounds[2 * d], hi = bounds[2 * d + 1];
        auto gap = [lo, hi](float x) { return std::max(0.0f, std::max(lo - x, x - hi)); };
        float g = gap(point[d]);
        if (circular_[d]) g = std::min(g, std::min(gap(point[d] - 2.0f), gap(point[d] + 2.0f)));
        sum += g * g;
    }
    return sum;
}

float RbfLattice::farthestDistance2(const float* bounds, const float* point) const {
    float sum = 0.0f;
    for (std::uint32_t d = 0; d < numContinuous_; ++d) {
        // On a circular sensor no centre is farther than 1 the shorter way round.
        float g = std::max(point[d] - bounds[2 * d], bounds[2 * d + 1] - point[d]);
        if (circular_[d]) g = 1.0f;
        sum += g * g;
    }
    return sum;
}

bool RbfLattice::scanCell(const Cell& c, const ScanParams& params, bool boxes, bool alone,
                                   std::vector<ActiveFeature>& out, LookupScratch& scratch) const {
    // The margin keeps an RBF whose distance rounds differently in the scan (a box distance is
    // never more than any of its centres' distances).
    const float reach = params.cutoff2 * 1.0001f;
    if (!alone && boxDistance2(c.bounds.data(), params.point) > reach) return false;
    const std::size_t n = out.size();
    const std::size_t count = c.features.size();
    const std::uint32_t* features = c.consecutive ? nullptr : c.features.data();
    const std::uint32_t firstFeature = c.firstFeature;
    bool nearOne = false;
    const std::size_t blocks = (count + kScanLanes - 1) / kScanLanes;
    // A cell of a few blocks (kReadWhole), or one wholly within the cutoff, is read whole;
    // otherwise runs of consecutive blocks within reach, each in one scan. The output grows by
    // whole blocks before each scan (its capacity is reused once warmed up).
    if (!boxes || count <= kReadWhole || farthestDistance2(c.bounds.data(), params.point) < params.cutoff2 * 0.9999f) {
        out.resize(n + blocks * kScanLanes);
        out.resize(n + kernels_->scan(params, c.centres.data(), features, firstFeature, count, out.data() + n, nearOne));
        return nearOne;
    }
    const std::size_t blockFloats = std::size_t(numContinuous_) * kScanLanes;
    std::size_t written = n;
    // Blocks within reach, up to 64 groups of 8 at a time; each run of consecutive ones is one scan.
    constexpr std::size_t kChunk = 64 * kScanLanes;
    std::uint8_t masks[kChunk / kScanLanes] = {};
    for (std::size_t chunk = 0; chunk < blocks; chunk += kChunk) {
        const std::size_t end = std::min(blocks, chunk + kChunk);
        kernels_->boxesWithin(params, c.blockBounds.data() + chunk / kScanLanes * boundsGroupFloats(), end - chunk,
                              reach, masks);
        scratch.blocksTested += static_cast<std::uint32_t>(end - chunk);
        // Runs of set bits, 64 blocks at a time (a run across two words is two scans).
        for (std::size_t w = chunk; w < end; w += 64) {
            std::uint64_t bits = 0;
            std::memcpy(&bits, masks + (w - chunk) / kScanLanes, sizeof bits);
            if (end - w < 64) bits &= (std::uint64_t(1) << (end - w)) - 1;
            scratch.blocksKept += static_cast<std::uint32_t>(__builtin_popcountll(bits));
            while (bits != 0) {
                const auto start = static_cast<std::size_t>(__builtin_ctzll(bits));
                const std::uint64_t rest = ~(bits >> start);
                const std::size_t length = rest == 0 ? 64 - start : static_cast<std::size_t>(__builtin_ctzll(rest));
                bits &= length + start >= 64 ? 0 : ~std::uint64_t(0) << (start + length);
                const std::size_t b = w + start;
                const std::size_t first = b * kScanLanes, last = std::min(count, (b + length) * kScanLanes);
                out.resize(written + length * kScanLanes);
                written += kernels_->scan(params, c.centres.data() + b * blockFloats,
                                          features != nullptr ? features + first : nullptr,
                                          firstFeature + static_cast<std::uint32_t>(first), last - first,
                                          out.data() + written, nearOne);
            }
        }
    }
    out.resize(written);
    return nearOne;
}

std::size_t RbfLattice::neighbourCandidates(const float* point, LookupScratch& scratch) const {
    // Distinct neighbouring cell coordinates per dimension (wrapping on circular sensors).
    auto& candidates = scratch.candidates;
    cellCoords(point, scratch.coords.data());
    std::size_t neighbours = 1;
    for (std::uint32_t d = 0; d < numContinuous_; ++d) {
        std::uint8_t n = 0;
        for (int off = -1; off <= 1; ++off) {
            std::int32_t c = scratch.coords[d] + off;
            if (circular_[d]) c = (c % cellsPerDim_ + cellsPerDim_) % cellsPerDim_;
            else if (c < 0 || c >= cellsPerDim_) continue;
            bool seen = false;
            for (std::uint8_t k = 0; k < n; ++k) seen |= candidates[d * 3 + k] == c;
            if (!seen) candidates[d * 3 + n++] = c;
        }
        scratch.candidateCount[d] = n;
        scratch.offsets[d] = 0;
        neighbours *= n;
    }
    return neighbours;
}

bool RbfLattice::find(const std::int32_t* discrete, const float* continuous,
                               std::vector<ActiveFeature>& out, LookupScratch& scratch, PrefetchQueue* ahead) const {
    // Without discrete sensors there is at most one array: begin() finds it without reading the
    // map's bucket array, one cache miss less for a crowd's update.
    auto arrayIt = keyCount_ == 1 ? arrays_.begin() : arrays_.find(discreteKey(discrete));
    if (arrayIt == arrays_.end()) return false;
    const auto& cells = arrayIt->second.cells;

    // An array of one cell (below resolution 16, or of at most kOneCellRbfs RBFs) is read whole: a lookup has at least
    // one neighbour cell, and skipping the candidates' scratch spares a crowd's update its misses.
    const std::size_t neighbours = cells.size() <= 1 ? 1 : neighbourCandidates(continuous, scratch);

    ScanParams params;
    params.point = continuous;
    params.circular = circular_.data();
    params.dims = numContinuous_;
    params.cutoff2 = kCutoffWidths * kCutoffWidths * sigma_ * sigma_;
    params.width2 = sigma_ * sigma_;
    params.negInv2Sigma2 = -1.0f / (2.0f * sigma_ * sigma_);
    params.ahead = ahead;
    bool nearOne = false;
    const bool boxes = scratch.wholeLookupsLeft == 0;
    if (!boxes) --scratch.wholeLookupsLeft;
    if (cells.size() <= neighbours) {
        // A coarse grid (low resolution, many sensors): the array has no more cells than the
        // neighbourhood, so reading them all costs no more and needs no hashing.
        for (const auto& entry : cells) nearOne |= scanCell(entry.second, params, boxes, cells.size() == 1, out, scratch);
    } else {
        auto& visited = scratch.visited;
        auto& offsets = scratch.offsets;
        visited.clear();
        while (true) {
            for (std::uint32_t d = 0; d < numContinuous_; ++d) scratch.neighbour[d] = scratch.candidates[d * 3 + offsets[d]];
            const std::uint64_t hash = cellHash(scratch.neighbour.data());
            auto cell = cells.find(hash);
            // Two neighbour cells whose hashes collide share one list: visit it once.
            if (cell != cells.end() && (exactCellKeys_ || std::find(visited.begin(), visited.end(), hash) == visited.end())) {
                if (!exactCellKeys_) visited.push_back(hash);
                nearOne |= scanCell(cell->second, params, boxes, false, out, scratch);
            }
            std::uint32_t d = 0;
            for (; d < numContinuous_; ++d) {  // odometer over the neighbour cells
                if (++offsets[d] < scratch.candidateCount[d]) break;
                offsets[d] = 0;
            }
            if (d == numContinuous_) break;
        }
    }
    if (boxes) judgeBoxes(scratch);
    return nearOne;
}

const RbfLattice::Array* RbfLattice::onlyArray() const noexcept {
    return keyCount_ == 1 && !arrays_.empty() ? &arrays_.begin()->second : nullptr;
}

const RbfLattice::Cell* RbfLattice::onlyCell() const noexcept {
    const Array* array = onlyArray();
    return array != nullptr && array->cells.size() == 1 ? &array->cells.begin()->second : nullptr;
}

void RbfLattice::prefetchLookup(unsigned stage) const noexcept {
    if (stage == 0) {
        if (const Array* array = onlyArray()) prefetchBytes(array, sizeof(*array));
        return;
    }
    const Cell* cell = onlyCell();
    if (cell == nullptr) return;
    if (stage == 1) {
        prefetchBytes(cell, sizeof(*cell));
    } else {
        prefetchData(cell->centres);
        if (!cell->consecutive) prefetchData(cell->features);
    }
}

void RbfLattice::addArraysTo(PrefetchQueue& q) const noexcept {
    if (const Cell* cell = onlyCell()) q.add(cell->centres.data(), cell->centres.size() * sizeof(float));
}

void RbfLattice::judgeBoxes(LookupScratch& scratch) const {
    if (scratch.blocksTested < kJudgeBlocks) return;
    // Skipped blocks save (dims + 1) * kScanLanes floats each, every box tested costs 2 * dims:
    // the boxes pay when kept / tested < 1 - dims / (4 (dims + 1)).
    const std::uint64_t perBlock = 4 * (std::uint64_t(numContinuous_) + 1);
    if (std::uint64_t(scratch.blocksKept) * perBlock > std::uint64_t(scratch.blocksTested) * (perBlock - numContinuous_)) {
        scratch.wholeLookupsLeft = kWholeLookups;
    }
    scratch.blocksTested = scratch.blocksKept = 0;
}

}  // namespace verve::core
