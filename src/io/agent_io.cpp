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

Agent agentFrom(const char* data, std::size_t size) {
    AgentSnapshot snapshot = io::looksBinary(data, size) ? io::snapshotFromBinary(data, size) : io::snapshotFromXml(data, size);
    return Agent(snapshot);  // the core checks what io cannot (e.g. the weight stride): Error(Format)
}

std::string encode(const Agent& agent, const SaveOptions& options) {
    const AgentSnapshot snapshot = agent.snapshot();
    return options.format == SaveFormat::Binary ? io::snapshotToBinary(snapshot, options.includeTraces)
                                                : io::snapshotToXml(snapshot, options.includeTraces);
}

}  // namespace

std::string saveAgentToString(const Agent& agent, const SaveOptions& options) {
    return naming("save", [&] { return encode(agent, options); });
}

void saveAgent(const Agent& agent, const std::string& path, const SaveOptions& options) {
    naming("save '" + path + "'", [&] {
        io::writeFileAtomically(path, encode(agent, options));
    });
}

Agent loadAgent(const std::string& path) {
    return naming("load '" + path + "'", [&] {
        const std::string data = io::readWholeFile(path);
        return agentFrom(data.data(), data.size());
    });
}

Agent loadAgentFromMemory(const char* data, std::size_t size) {
    return naming("load from memory", [&] { return agentFrom(data, size); });
}

}  // namespace verve
