// One brain, many bodies: a shared learner and the agents (bodies) that step through it.
#include <atomic>
#include <memory>
#include <new>
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
    // Shared with every body (verve_agent::brainInUse): a call on the brain or on any of its bodies
    // holds it, so two threads never touch the shared weights at once.
    std::shared_ptr<verve::capi::InUseFlag> inUse = std::make_shared<verve::capi::InUseFlag>(false);
    // Held by the calls on this handle only: verve_brain_destroy refuses while one runs (a body's
    // calls do not need the handle, which they outlive).
    mutable verve::capi::InUseFlag handleInUse{false};
    // Shared with every body: a change through one body makes the brain's and every body's kept save stale.
    verve::capi::ChangeCounter changes = verve::capi::newChangeCounter();
    // verve_brain_save_memory's (and _binary's) size query, kept for the call with a buffer.
    // Mutable: a save is a const call (a brain is used by one thread at a time).
    mutable verve::capi::KeptSave save;
};

namespace {

using verve::capi::guarded;
using verve::capi::requireArg;

// One call's exclusive use of a brain and its bodies (capi_in_use.hpp).
class BrainUse {
public:
    explicit BrainUse(const verve_brain* handle) {
        requireArg(handle, "brain");
        use_.take(handle->handleInUse);
        use_.takeShared(*handle->inUse);
    }

private:
    verve::capi::InUse use_;
};

void handOutBrain(verve::Brain&& brain, verve_brain** out) { *out = new verve_brain(std::move(brain)); }

// Serialised under the flag, written after it is given back: a brain's autosave never holds up
// its bodies' updates for the disk (write, flush, rename).
void saveToFile(const verve_brain* brain, const char* path, verve::SaveFormat format) {
    std::string bytes;
    {
        const BrainUse use(brain);
        requireArg(path, "path");
        bytes = verve::saveBrainToString(brain->brain, format);
    }
    verve::writeSaveFile(path, bytes);
}

// The two-call buffer save of either format, serialised once for both calls.
void saveToMemory(const verve_brain* brain, void* buffer, size_t* size, verve::SaveFormat format) {
    const BrainUse use(brain);
    requireArg(size, "size");
    brain->save.serve(format, *brain->changes, [&] { return verve::saveBrainToString(brain->brain, format); }, buffer, *size);
}

}  // namespace

extern "C" {

VERVE_API verve_result VERVE_CALL verve_brain_create(const verve_agent_desc* desc, verve_brain** out) {
    return guarded(__func__, [&] {
        requireArg(desc, "desc");
        requireArg(out, "out");
        handOutBrain(verve::Brain(verve::capi::toDescriptor(*desc)), out);
    });
}

VERVE_API void VERVE_CALL verve_brain_destroy(verve_brain* brain) {
    if (brain == nullptr) return;
    // Freeing a brain a call is inside would crash that call: it stays alive instead (as
    // verve_agent_destroy does). Its bodies' calls do not use the handle: they may go on.
    if (!verve::capi::tryAcquire(brain->handleInUse)) {
        verve::capi::recordError(__func__, VERVE_ERROR_INVALID_STATE, "the brain is in use by another call: not destroyed");
        return;
    }
    delete brain;
}

VERVE_API verve_result VERVE_CALL verve_brain_create_body(verve_brain* brain, verve_agent** out_body) {
    return guarded(__func__, [&] {
        const BrainUse use(brain);
        requireArg(out_body, "out_body");
        // The handle's memory first: makeBody numbers the body (its random stream), so nothing
        // after it may fail, or a retried call would make a body with another stream.
        struct Room {
            void* p = ::operator new(sizeof(verve_agent));
            ~Room() { ::operator delete(p); }
        } room;
        auto* body = new (room.p) verve_agent(brain->brain.makeBody());
        room.p = nullptr;
        body->brainInUse = brain->inUse;
        body->shareChangesWith(brain->changes);
        *out_body = body;
    });
}

VERVE_API verve_result VERVE_CALL verve_brain_get_rbf_count(const verve_brain* brain, uint32_t* out_count) {
    return guarded(__func__, [&] {
        const BrainUse use(brain);
        const verve::Brain& b = brain->brain;
        requireArg(out_count, "out_count");
        *out_count = static_cast<uint32_t>(b.rbfCount());
    });
}

VERVE_API verve_result VERVE_CALL verve_brain_save(const verve_brain* brain, const char* path) {
    return guarded(__func__, [&] { saveToFile(brain, path, verve::SaveFormat::Xml); });
}

VERVE_API verve_result VERVE_CALL verve_brain_save_binary(const verve_brain* brain, const char* path) {
    return guarded(__func__, [&] { saveToFile(brain, path, verve::SaveFormat::Binary); });
}

VERVE_API verve_result VERVE_CALL verve_brain_load(const char* path, verve_brain** out) {
    return guarded(__func__, [&] {
        requireArg(path, "path");
        requireArg(out, "out");
        handOutBrain(verve::loadBrain(path), out);
    });
}

VERVE_API verve_result VERVE_CALL verve_brain_save_memory(const verve_brain* brain, void* buffer, size_t* size) {
    return guarded(__func__, [&] { saveToMemory(brain, buffer, size, verve::SaveFormat::Xml); });
}

VERVE_API verve_result VERVE_CALL verve_brain_save_memory_binary(const verve_brain* brain, void* buffer, size_t* size) {
    return guarded(__func__, [&] { saveToMemory(brain, buffer, size, verve::SaveFormat::Binary); });
}

VERVE_API verve_result VERVE_CALL verve_brain_load_memory(const void* data, size_t size, verve_brain** out) {
    return guarded(__func__, [&] {
        requireArg(data, "data");
        requireArg(out, "out");
        handOutBrain(verve::loadBrainFromMemory(static_cast<const char*>(data), size), out);
    });
}

}  // extern "C"
