// A teacher's judgement of continuous actions (core/teacher.hpp): each remembered act's gradients
// (the natural gradient of log N(u; x, sigma) at the value it played, as the actor's trace gathers
// it) are weighed by its features' activations, and a judgement moves each (feature, column)
// weight by rate * praise * the largest activation * the activation-weighted mean gradient. The mean,
// not the sum: as the discrete acts' replacing trace, a judgement then weighs the same at 10 or 60
// updates a second. Kept within +-ContinuousPolicy::kWeightBound, as every continuous weight.
#include <algorithm>

#include "core/continuous_actions.hpp"
#include "core/teacher.hpp"
#include "core/weight_table.hpp"

namespace verve::core {

void TeacherMemory::gatherContinuous() {
    continuousScratch_.clear();
    if (continuousColumns_ == 0) return;
    continuousScratch_.reserve((pool_.size() - (first_ < acts_.size() ? acts_[first_].begin : pool_.size())) *
                               continuousColumns_);
    for (std::size_t i = first_; i < acts_.size(); ++i) {
        const Act& a = acts_[i];
        const float* g = gradients_.data() + i * continuousColumns_;
        for (std::uint32_t k = 0; k < a.count; ++k) {
            const ActiveFeature& f = pool_[a.begin + k];
            for (std::uint32_t c = 0; c < continuousColumns_; ++c) {
                continuousScratch_.push_back(ContinuousCredit{f.index, c, f.activation, g[c]});
            }
        }
    }
    std::sort(continuousScratch_.begin(), continuousScratch_.end(), [](const ContinuousCredit& x, const ContinuousCredit& y) {
        return x.feature != y.feature ? x.feature < y.feature : x.column < y.column;
    });
}

void TeacherMemory::creditContinuous(WeightTable& w, float praise, float rate, std::uint32_t firstColumn) noexcept {
    for (std::size_t i = 0; i < continuousScratch_.size();) {
        const ContinuousCredit& first = continuousScratch_[i];
        float weighted = 0.0f, total = 0.0f, largest = 0.0f;
        std::size_t j = i;
        for (; j < continuousScratch_.size() && continuousScratch_[j].feature == first.feature &&
               continuousScratch_[j].column == first.column;
             ++j) {
            weighted += continuousScratch_[j].gradient * continuousScratch_[j].activation;
            total += continuousScratch_[j].activation;
            largest = std::max(largest, continuousScratch_[j].activation);
        }
        if (first.feature < w.rows() && total > 0.0f) {
            float& weight = w.row(first.feature)[WeightLayout::kPolicy + firstColumn + first.column];
            weight = std::clamp(weight + rate * praise * largest * (weighted / total), -ContinuousPolicy::kWeightBound,
                                ContinuousPolicy::kWeightBound);
        }
        i = j;
    }
}

}  // namespace verve::core
