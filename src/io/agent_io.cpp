// verve/io.hpp: the agent's snapshot as XML or binary, to a file (atomically) or to memory.
#include "verve/io.hpp"

#include "io/atomic_file.hpp"
#include "io/snapshot_binary.hpp"
#include "io/snapshot_xml.hpp"

namespace verve {
namespace {

std::string withContext(const std::string& context, const char* message) { return context + ": " + message; }

// Errors name the save they concern, so a host juggling many files can tell which one failed.
template <typename F>
auto naming(const std::string& context, F&& body) -> decltype(body()) {
    try {
        return body();
    } catch (const Error& e) {
        throw Error(e.code(), withContext(context, e.what()));
    }
}

AgentSnapshot snapshotFrom(const char* data, std::size_t size) {
    return io::looksBinary(data, size) ? io::snapshotFromBinary(data, size) : io::snapshotFromXml(data, size);
}

// Agent or Brain: the core checks what io cannot (e.g. the weight stride): Error(Format).
template <typename Learner>
Learner from(const char* data, std::size_t size) {
    return Learner(snapshotFrom(data, size));
}

template <typename Learner>
Learner load(const std::string& path) {
    return naming("load '" + path + "'", [&] {
        const std::string data = io::readWholeFile(path);
        return from<Learner>(data.data(), data.size());
    });
}

std::string encode(const AgentSnapshot& snapshot, const SaveOptions& options) {
    return options.format == SaveFormat::Binary ? io::snapshotToBinary(snapshot, options.includeTraces)
                                                : io::snapshotToXml(snapshot, options.includeTraces);
}

// A brain has no short-term memory to save.
SaveOptions brainOptions(SaveFormat format) { return SaveOptions{false, format}; }

void save(const AgentSnapshot& snapshot, const std::string& path, const SaveOptions& options) {
    writeSaveFile(path, encode(snapshot, options));
}

}  // namespace

void writeSaveFile(const std::string& path, const std::string& bytes) {
    naming("save '" + path + "'", [&] { io::writeFileAtomically(path, bytes); });
}

std::string saveAgentToString(const Agent& agent, const SaveOptions& options) {
    return naming("save", [&] { return encode(agent.snapshot(), options); });
}

void saveAgent(const Agent& agent, const std::string& path, const SaveOptions& options) {
    save(agent.snapshot(), path, options);
}

Agent loadAgent(const std::string& path) { return load<Agent>(path); }

Agent loadAgentFromMemory(const char* data, std::size_t size) {
    return naming("load from memory", [&] { return from<Agent>(data, size); });
}

std::string saveBrainToString(const Brain& brain, SaveFormat format) {
    return naming("save", [&] { return encode(brain.snapshot(), brainOptions(format)); });
}

void saveBrain(const Brain& brain, const std::string& path, SaveFormat format) {
    save(brain.snapshot(), path, brainOptions(format));
}

Brain loadBrain(const std::string& path) { return load<Brain>(path); }

Brain loadBrainFromMemory(const char* data, std::size_t size) {
    return naming("load from memory", [&] { return from<Brain>(data, size); });
}

}  // namespace verve
