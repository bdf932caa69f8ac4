// The raycast NPCs' scripted baseline, as a game designer would write it: context steering over
// the same sensors and actions the agents get, so the two curves compare like for like.
#pragma once
#include <cstdint>

#include "ray_npc.hpp"

namespace verve::scenes {

// Seek the target through the free ray closest to it (a ray is free when nothing lies within a
// metre, or the target is nearer than the hit); turn in place when the target is behind or every
// ray is blocked; never walk into a hazard ahead; keep walking out of a hazard once inside.
std::uint32_t scriptedSteering(const Observation& obs, const RayNpcConfig& config);

}  // namespace verve::scenes
