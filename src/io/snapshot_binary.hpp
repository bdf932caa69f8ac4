// AgentSnapshot <-> the compact binary save (docs/c-api.md, "Persistence"). Little-endian, fixed
// layout, no padding:
//
//   header  : magic "VERVEBIN" (8 bytes) | u32 binary format version | u32 0 | u64 payload bytes |
//             u64 checksum of the payload (payloadChecksum)
//   payload : descriptor | state | features | weights | short-term memory (present: u8 0/1), the
//             order and types of AgentSnapshot's fields; every list is a u64 count then its items.
//
// Floats are stored as their bits, so every value survives the round trip; the same agent gives
// the same bytes. Loading bounds every count by the bytes that remain before allocating.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "verve/agent_snapshot.hpp"

namespace verve::io {

inline constexpr char kBinaryMagic[8] = {'V', 'E', 'R', 'V', 'E', 'B', 'I', 'N'};
// 2: the reward range; 3: model_predicts_change; 4: the final reward range
inline constexpr std::uint32_t kBinaryFormatVersion = 9;  // 6: sensor groups, 7: action branches
// 8: continuous actions, 9: group rates
inline constexpr std::size_t kBinaryHeaderBytes = 32;

// True when `data` starts like a binary save (a prefix of the magic counts, so that a save cut
// inside its magic is reported as a truncated binary save rather than as bad XML).
bool looksBinary(const char* data, std::size_t size);

// Throws Error(Internal) if the snapshot is inconsistent (it would not load back).
std::string snapshotToBinary(const AgentSnapshot& snapshot, bool includeTraces);

// Throws Error(Format) naming what is wrong (truncated, checksum mismatch, inconsistent),
// Error(Version) for a newer binary format version.
AgentSnapshot snapshotFromBinary(const char* data, std::size_t size);

// 64-bit hash of the payload, 8 bytes per step: every step is a bijection of the running state,
// so any single changed bit (or a changed length) changes the result.
std::uint64_t payloadChecksum(const char* data, std::size_t size);

}  // namespace verve::io
