#include "core/teacher.hpp"

#include <algorithm>

#include "core/weight_table.hpp"

namespace verve::core {

void TeacherMemory::reserve(std::size_t features, std::uint32_t continuousColumns) {
    // remember() only forgets and compacts before it appends, so room for one more act as things
    // are now is room enough; compaction keeps both vectors within about twice what is remembered.
    reserveRoom(acts_, acts_.size() + 1);
    reserveRoom(pool_, pool_.size() + features);
    reserveRoom(gradients_, (acts_.size() + 1) * std::size_t(continuousColumns));
    continuousColumns_ = continuousColumns;
}

void TeacherMemory::remember(float dt, std::uint32_t action, const std::vector<ActiveFeature>& phi,
                             const float* continuous) noexcept {
    clock_ += dt;
    forgetBefore(clock_ - kWindowSeconds);
    if (acts() >= kMaxActs) ++first_;
    compact();
    const std::size_t c = continuousColumns_;
    if (acts_.size() == acts_.capacity() || pool_.size() + phi.size() > pool_.capacity() ||
        gradients_.size() + c > gradients_.capacity()) {
        return;  // reserve() was not called
    }
    acts_.push_back(Act{clock_, action, static_cast<std::uint32_t>(pool_.size()), static_cast<std::uint32_t>(phi.size())});
    pool_.insert(pool_.end(), phi.begin(), phi.end());
    if (continuous != nullptr) gradients_.insert(gradients_.end(), continuous, continuous + c);
    else gradients_.resize(gradients_.size() + c, 0.0f);
}

void TeacherMemory::forgetBefore(double time) noexcept {
    while (first_ < acts_.size() && acts_[first_].time < time) ++first_;
}

void TeacherMemory::compact() noexcept {
    if (first_ == 0 || 2 * first_ < acts_.size()) return;
    const std::uint32_t shift = first_ < acts_.size() ? acts_[first_].begin : static_cast<std::uint32_t>(pool_.size());
    gradients_.erase(gradients_.begin(), gradients_.begin() + static_cast<std::ptrdiff_t>(first_ * continuousColumns_));
    acts_.erase(acts_.begin(), acts_.begin() + static_cast<std::ptrdiff_t>(first_));
    first_ = 0;
    for (Act& a : acts_) a.begin -= shift;
    pool_.erase(pool_.begin(), pool_.begin() + shift);
}

void TeacherMemory::credit(WeightTable& w, float praise, float rate, const PolicyRange& range,
                           const ActionBranches& branches) {
    forgetBefore(clock_ - kWindowSeconds);
    scratch_.clear();
    scratch_.reserve(pool_.size() * branches.count);  // may throw: nothing has changed yet
    gatherContinuous();                                // may throw too, before any change
    for (std::size_t i = first_; i < acts_.size(); ++i) {
        const Act& a = acts_[i];
        std::uint32_t column[ActionBranches::kMax];
        const std::uint32_t columns = branches.columnsOf(a.action, column);
        for (std::uint32_t k = 0; k < a.count; ++k) {
            const ActiveFeature& f = pool_[a.begin + k];
            if (f.index >= w.rows()) continue;
            for (std::uint32_t b = 0; b < columns; ++b) scratch_.push_back(Credit{f.index, column[b], f.activation});
        }
    }
    // One credit per (feature, action): the largest activation, as a replacing trace.
    std::sort(scratch_.begin(), scratch_.end(), [](const Credit& x, const Credit& y) {
        return x.feature != y.feature ? x.feature < y.feature : x.action != y.action ? x.action < y.action : x.activation > y.activation;
    });
    for (std::size_t i = 0; i < scratch_.size(); ++i) {
        const Credit& c = scratch_[i];
        if (i > 0 && scratch_[i - 1].feature == c.feature && scratch_[i - 1].action == c.action) continue;
        float& weight = w.row(c.feature)[WeightLayout::kPolicy + c.action];
        const float step = rate * praise * c.activation;
        // Praise moves a weight only within +-kPraiseReach (what the game's rewards taught beyond it
        // stays): a pet scolded whatever it does ends with its scolded acts alike at the floor,
        // choosing among them as at the start, not frozen into the one it was scolded least for.
        if (step > 0.0f) weight = std::max(weight, std::min(weight + step, kPraiseReach));
        else weight = std::min(weight, std::max(weight + step, -kPraiseReach));
        weight = range.clamp(weight);
    }
    creditContinuous(w, praise, rate, branches.columns);
}

}  // namespace verve::core
