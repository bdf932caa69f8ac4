// Saving and loading agents as XML (src/io, pugixml) or as a compact binary save (checksummed,
// several times faster). Saves to a path are atomic: a temporary file is written, flushed and
// renamed over the target, so a crash leaves the old save intact. Loading recognises either format.
#pragma once
#include <cstddef>
#include <string>

#include "verve/agent.hpp"
#include "verve/brain.hpp"

namespace verve {

enum class SaveFormat {
    Xml,     // readable text, format version AgentSnapshot::kFormatVersion
    Binary,  // little-endian, checksummed (src/io/snapshot_binary.hpp)
};

struct SaveOptions {
    bool includeTraces = true;  // eligibility traces and the previous step (resume mid-trial)
    SaveFormat format = SaveFormat::Xml;
};

void saveAgent(const Agent& agent, const std::string& path, const SaveOptions& options = {});
// Writes bytes a *ToString save made to `path`, crash-safely as saveAgent does (a temporary file
// next to it, flushed, renamed over it, the folder flushed; the old file's permissions kept). The
// C ABI serialises under the agent's in-use flag and writes with this after giving the flag back,
// so a slow disk never holds up the agent's (or a brain's bodies') updates. Throws Error(Io).
void writeSaveFile(const std::string& path, const std::string& bytes);
std::string saveAgentToString(const Agent& agent, const SaveOptions& options = {});

// Throw Error(Io) when the file cannot be read, Error(Format) naming what is wrong for a corrupt
// or truncated save, Error(Version) for a newer format. Either format, told by its first bytes.
Agent loadAgent(const std::string& path);
Agent loadAgentFromMemory(const char* data, std::size_t size);

// A shared brain is saved as an agent without short-term memory (the same formats, XML or
// binary): either kind of save loads as a Brain (its RBFs and weights) or as an Agent.
void saveBrain(const Brain& brain, const std::string& path, SaveFormat format = SaveFormat::Xml);
std::string saveBrainToString(const Brain& brain, SaveFormat format = SaveFormat::Xml);
Brain loadBrain(const std::string& path);
Brain loadBrainFromMemory(const char* data, std::size_t size);

}  // namespace verve
