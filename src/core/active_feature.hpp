// One active feature of an observation: which RBF, and how strongly it responds.
#pragma once
#include <cstdint>

namespace verve::core {

struct ActiveFeature {
    // Deliberately leaves its fields uninitialised: the activation scan resizes its output to
    // every candidate, then overwrites them, and value-initialising would cost a pass of its own.
    ActiveFeature() noexcept {}  // NOLINT(cppcoreguidelines-pro-type-member-init)
    ActiveFeature(std::uint32_t i, float a) noexcept : index(i), activation(a) {}

    std::uint32_t index;
    float activation;  // in (0, 1]
};

}  // namespace verve::core
