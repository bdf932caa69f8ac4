// verve/io.hpp: the agent's snapshot as XML, to a file (atomically) or to memory.
#include "verve/io.hpp"

#include "io/atomic_file.hpp"
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

// Agent or Brain: the core checks what io cannot (e.g. the weight stride): Error(Format).
template <typename Learner>
Learner fromXml(const char* data, std::size_t size) {
    return Learner(io::snapshotFromXml(data, size));
}

template <typename Learner>
Learner load(const std::string& path) {
    return naming("load '" + path + "'", [&] {
        const std::string data = io::readWholeFile(path);
        return fromXml<Learner>(data.data(), data.size());
    });
}

void save(const AgentSnapshot& snapshot, const std::string& path, bool includeTraces) {
    naming("save '" + path + "'", [&] { io::writeFileAtomically(path, io::snapshotToXml(snapshot, includeTraces)); });
}

}  // namespace

std::string saveAgentToString(const Agent& agent, const SaveOptions& options) {
    return naming("save", [&] { return io::snapshotToXml(agent.snapshot(), options.includeTraces); });
}

void saveAgent(const Agent& agent, const std::string& path, const SaveOptions& options) {
    save(agent.snapshot(), path, options.includeTraces);
}

Agent loadAgent(const std::string& path) { return load<Agent>(path); }

Agent loadAgentFromMemory(const char* data, std::size_t size) {
    return naming("load from memory", [&] { return fromXml<Agent>(data, size); });
}

std::string saveBrainToString(const Brain& brain) {
    return naming("save", [&] { return io::snapshotToXml(brain.snapshot(), false); });
}

void saveBrain(const Brain& brain, const std::string& path) { save(brain.snapshot(), path, false); }

Brain loadBrain(const std::string& path) { return load<Brain>(path); }

Brain loadBrainFromMemory(const char* data, std::size_t size) {
    return naming("load from memory", [&] { return fromXml<Brain>(data, size); });
}

}  // namespace verve
