// One brain, many bodies: a shared learner and the agents (bodies) that step through it.
#include <string>
#include <utility>

#include "capi/capi_agent.hpp"
#include "capi/capi_buffer.hpp"
#include "capi/capi_desc.hpp"
#include "verve/brain.hpp"
#include "verve/io.hpp"

struct verve_brain {
    explicit verve_brain(verve::Brain&& b) : brain(std::move(b)) {}
    verve::Brain brain;
};

namespace {

using verve::capi::guarded;
using verve::capi::requireArg;

verve::Brain& brainOf(verve_brain* handle) {
    requireArg(handle, "brain");
    return handle->brain;
}

const verve::Brain& brainOf(const verve_brain* handle) {
    requireArg(handle, "brain");
    return handle->brain;
}

void handOutBrain(verve::Brain&& brain, verve_brain** out) { *out = new verve_brain(std::move(brain)); }

}  // namespace

extern "C" {

VERVE_API verve_result VERVE_CALL verve_brain_create(const verve_agent_desc* desc, verve_brain** out) {
    return guarded(__func__, [&] {
        requireArg(desc, "desc");
        requireArg(out, "out");
        handOutBrain(verve::Brain(verve::capi::toDescriptor(*desc)), out);
    });
}

VERVE_API void VERVE_CALL verve_brain_destroy(verve_brain* brain) { delete brain; }

VERVE_API verve_result VERVE_CALL verve_brain_create_body(verve_brain* brain, verve_agent** out_body) {
    return guarded(__func__, [&] {
        verve::Brain& b = brainOf(brain);
        requireArg(out_body, "out_body");
        verve::capi::handOut(b.makeBody(), out_body);
    });
}

VERVE_API verve_result VERVE_CALL verve_brain_get_rbf_count(const verve_brain* brain, uint32_t* out_count) {
    return guarded(__func__, [&] {
        const verve::Brain& b = brainOf(brain);
        requireArg(out_count, "out_count");
        *out_count = static_cast<uint32_t>(b.rbfCount());
    });
}

VERVE_API verve_result VERVE_CALL verve_brain_save(const verve_brain* brain, const char* path) {
    return guarded(__func__, [&] {
        const verve::Brain& b = brainOf(brain);
        requireArg(path, "path");
        verve::saveBrain(b, path);
    });
}

VERVE_API verve_result VERVE_CALL verve_brain_load(const char* path, verve_brain** out) {
    return guarded(__func__, [&] {
        requireArg(path, "path");
        requireArg(out, "out");
        handOutBrain(verve::loadBrain(path), out);
    });
}

VERVE_API verve_result VERVE_CALL verve_brain_save_memory(const verve_brain* brain, void* buffer, size_t* size) {
    return guarded(__func__, [&] {
        const verve::Brain& b = brainOf(brain);
        requireArg(size, "size");
        verve::capi::copyOut(verve::saveBrainToString(b), buffer, *size);
    });
}

VERVE_API verve_result VERVE_CALL verve_brain_load_memory(const void* data, size_t size, verve_brain** out) {
    return guarded(__func__, [&] {
        requireArg(data, "data");
        requireArg(out, "out");
        handOutBrain(verve::loadBrainFromMemory(static_cast<const char*>(data), size), out);
    });
}

}  // extern "C"
