// AgentSnapshot <-> XML text (format version AgentSnapshot::kFormatVersion). The layout:
//
//   <verve_agent format_version="1">
//     <descriptor resolution=".." actions=".." allocation="dynamic|full" tau_value=".." ... seed=".." ...>
//       <discrete_sensor values="20"/>  <continuous_sensor circular="false"/>
//       <sensor_group sensors="3"/> (format 2)  <action_branch choices="3"/> (format 3)
//     </descriptor>
//     <state learning="true" steps=".." model_error=".." last_dt=".." rng="s0 s1 s2 s3"/>
//     <features count="N"> <keys>..</keys> <centres>..</centres> </features>
//     <weights stride="S">N rows of S numbers</weights>
//     <traces stride="T" count="M"> <features>..</features> <values>..</values> </traces>      (optional)
//     <previous action=".."> <features/> <activations/> <discrete/> <continuous/> </previous> (optional)
//   </verve_agent>
//
// Floats are written in their shortest exact form, so every bit survives the round trip.
#pragma once
#include <cstddef>
#include <string>

#include "verve/agent_snapshot.hpp"

namespace verve::io {

inline constexpr const char* kRootElement = "verve_agent";

// Throws Error(Internal) if the snapshot is inconsistent (it would not load back).
std::string snapshotToXml(const AgentSnapshot& snapshot, bool includeTraces);

// Throws Error(Format) naming what is wrong, Error(Version) for a newer format version.
AgentSnapshot snapshotFromXml(const char* data, std::size_t size);

}  // namespace verve::io
