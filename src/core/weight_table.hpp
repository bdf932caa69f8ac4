// Learned parameters, one contiguous row per feature: [value, policy[A], continuous[2C], model outputs...].
// One active feature is one cache walk, whichever network reads it.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace verve::core {

// Makes room for n elements ahead of a change, growing geometrically: an update reserves
// everything it may need first, so an allocation failure throws before anything has changed.
template <typename Vector>
void reserveRoom(Vector& v, std::size_t n) {
    if (v.capacity() < n) v.reserve(std::max(n, 2 * v.capacity()));
}

struct WeightLayout {
    std::uint32_t numActions = 0;    // actor columns: discrete neurons, then continuous actions' (2 each)
    std::uint32_t modelColumns = 0;  // predictive-model weights per feature (0 without planning)

    static constexpr std::uint32_t kValue = 0;
    static constexpr std::uint32_t kPolicy = 1;
    std::uint32_t modelOffset() const { return kPolicy + numActions; }
    std::uint32_t stride() const { return kPolicy + numActions + modelColumns; }
};

class WeightTable {
public:
    explicit WeightTable(WeightLayout layout) : layout_(layout) {}

    const WeightLayout& layout() const { return layout_; }
    std::uint32_t stride() const { return layout_.stride(); }
    std::uint32_t rows() const { return static_cast<std::uint32_t>(data_.size() / layout_.stride()); }

    // New features start at zero: value 0 and equal action probabilities (thesis chapter 4).
    void resize(std::uint32_t rows) { data_.resize(std::size_t(rows) * layout_.stride(), 0.0f); }
    void reserve(std::uint32_t rows) { reserveRoom(data_, std::size_t(rows) * layout_.stride()); }

    float* row(std::uint32_t feature) { return data_.data() + std::size_t(feature) * layout_.stride(); }
    const float* row(std::uint32_t feature) const { return data_.data() + std::size_t(feature) * layout_.stride(); }

    std::vector<float>& data() { return data_; }
    const std::vector<float>& data() const { return data_; }

private:
    WeightLayout layout_;
    std::vector<float> data_;
};

}  // namespace verve::core
