// An observation of one discrete sensor, shared by the core tests.
#pragma once
#include <cstdint>

#include "verve/observation.hpp"

namespace verve::coretest {

inline Observation discreteObs(std::int32_t v) {
    Observation o;
    o.discrete = {v};
    return o;
}

}  // namespace verve::coretest
