// Saving and loading agents: XML files (atomic) and memory buffers (two-call size pattern).
#include <cstring>
#include <string>

#include "capi/capi_agent.hpp"
#include "capi/capi_buffer.hpp"
#include "verve/io.hpp"

using verve::capi::AgentUse;
using verve::capi::guarded;
using verve::capi::requireArg;

extern "C" {

VERVE_API verve_result VERVE_CALL verve_agent_save(const verve_agent* agent, const char* path) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(path, "path");
        verve::saveAgent(a, path);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_load(const char* path, verve_agent** out) {
    return guarded(__func__, [&] {
        requireArg(path, "path");
        requireArg(out, "out");
        verve::capi::handOut(verve::loadAgent(path), out);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_save_memory(const verve_agent* agent, void* buffer, size_t* size) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(size, "size");
        // Serialised once for both calls: the size query keeps its bytes for the call with a buffer.
        const std::string* kept = agent->keptSave();
        if (kept == nullptr) {
            agent->keepSave(verve::saveAgentToString(a));
            kept = agent->keptSave();
        }
        verve::capi::copyOut(*kept, buffer, *size);
        if (buffer != nullptr) agent->dropSave();  // delivered: free the copy
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_load_memory(const void* data, size_t size, verve_agent** out) {
    return guarded(__func__, [&] {
        requireArg(data, "data");
        requireArg(out, "out");
        verve::capi::handOut(verve::loadAgentFromMemory(static_cast<const char*>(data), size), out);
    });
}

}  // extern "C"
