// Saving and loading agents, XML or binary: files (atomic) and memory buffers (two-call size
// pattern). Loading tells the formats apart by their first bytes.
#include <string>

#include "capi/capi_agent.hpp"
#include "verve/io.hpp"

using verve::capi::AgentUse;
using verve::capi::guarded;
using verve::capi::requireArg;

namespace {

verve::SaveOptions inFormat(verve::SaveFormat format) {
    verve::SaveOptions options;
    options.format = format;
    return options;
}

// Serialised under the in-use flag, written after it is given back: the disk (write, flush,
// rename) never holds up the agent's next update, nor, for a body, its brain's other bodies.
void saveToFile(const verve_agent* agent, const char* path, verve::SaveFormat format) {
    std::string bytes;
    {
        const AgentUse use(agent);
        requireArg(path, "path");
        bytes = verve::saveAgentToString(use.agent(), inFormat(format));
    }
    verve::writeSaveFile(path, bytes);
}

// The two-call buffer save of either format.
void saveToMemory(const verve_agent* agent, void* buffer, size_t* size, verve::SaveFormat format) {
    const AgentUse use(agent);
    const verve::Agent& a = use.agent();
    requireArg(size, "size");
    agent->saveToBuffer(format, [&] { return verve::saveAgentToString(a, inFormat(format)); }, buffer, *size);
}

}  // namespace

extern "C" {

VERVE_API verve_result VERVE_CALL verve_agent_save(const verve_agent* agent, const char* path) {
    return guarded(__func__, [&] { saveToFile(agent, path, verve::SaveFormat::Xml); });
}

VERVE_API verve_result VERVE_CALL verve_agent_save_binary(const verve_agent* agent, const char* path) {
    return guarded(__func__, [&] { saveToFile(agent, path, verve::SaveFormat::Binary); });
}

VERVE_API verve_result VERVE_CALL verve_agent_load(const char* path, verve_agent** out) {
    return guarded(__func__, [&] {
        requireArg(path, "path");
        requireArg(out, "out");
        verve::capi::handOut(verve::loadAgent(path), out);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_save_memory(const verve_agent* agent, void* buffer, size_t* size) {
    return guarded(__func__, [&] { saveToMemory(agent, buffer, size, verve::SaveFormat::Xml); });
}

VERVE_API verve_result VERVE_CALL verve_agent_save_memory_binary(const verve_agent* agent, void* buffer, size_t* size) {
    return guarded(__func__, [&] { saveToMemory(agent, buffer, size, verve::SaveFormat::Binary); });
}

VERVE_API verve_result VERVE_CALL verve_agent_load_memory(const void* data, size_t size, verve_agent** out) {
    return guarded(__func__, [&] {
        requireArg(data, "data");
        requireArg(out, "out");
        verve::capi::handOut(verve::loadAgentFromMemory(static_cast<const char*>(data), size), out);
    });
}

}  // extern "C"
