// Recordings of demonstrated steps (include/verve/recording.hpp) behind the C ABI.
#include <string>
#include <utility>

#include "capi/capi_agent.hpp"
#include "capi/capi_buffer.hpp"
#include "capi/capi_guard.hpp"
#include "capi/capi_in_use.hpp"
#include "verve/recording.hpp"

struct verve_recording {
    explicit verve_recording(verve::Recording&& r) : recording(std::move(r)) {}
    verve::Recording recording;
    // Set for the duration of every call on this recording (read-only calls too: one thread at a time).
    mutable verve::capi::InUseFlag inUse{false};
};

namespace {

using verve::capi::AgentUse;
using verve::capi::guarded;
using verve::capi::requireArg;

// One call's exclusive use of a recording.
template <typename Handle>
class RecordingUse {
public:
    explicit RecordingUse(Handle* handle) : handle_(handle) {
        requireArg(handle, "recording");
        use_.take(handle->inUse);
    }
    auto& recording() const { return handle_->recording; }

private:
    Handle* handle_;
    verve::capi::InUse use_;
};

void handOut(verve::Recording&& r, verve_recording** out) { *out = new verve_recording(std::move(r)); }

}  // namespace

extern "C" {

VERVE_API verve_result VERVE_CALL verve_recording_create(const verve_agent* shaped_like, verve_recording** out) {
    return guarded(__func__, [&] {
        const AgentUse use(shaped_like);
        requireArg(out, "out");
        handOut(verve::Recording::shapedLike(use.agent().descriptor()), out);
    });
}

VERVE_API void VERVE_CALL verve_recording_destroy(verve_recording* recording) {
    if (recording == nullptr) return;
    // Freeing a recording a call is inside would crash that call: it stays alive instead.
    if (!verve::capi::tryAcquire(recording->inUse)) {
        verve::capi::recordError(__func__, VERVE_ERROR_INVALID_STATE, "the recording is in use by another call: not destroyed");
        return;
    }
    delete recording;
}

VERVE_API verve_result VERVE_CALL verve_recording_add_step(verve_recording* recording, float reward, const int32_t* discrete,
                                                           uint32_t n_discrete, const float* continuous,
                                                           uint32_t n_continuous, float dt, uint32_t action) {
    return guarded(__func__, [&] {
        const RecordingUse use(recording);
        if (n_discrete > 0) requireArg(discrete, "discrete (with n_discrete > 0)");
        if (n_continuous > 0) requireArg(continuous, "continuous (with n_continuous > 0)");
        use.recording().addStep(reward, verve::ObservationView{discrete, n_discrete, continuous, n_continuous}, dt, action);
    });
}

VERVE_API verve_result VERVE_CALL verve_recording_add_step_continuous(
    verve_recording* recording, float reward, const int32_t* discrete, uint32_t n_discrete, const float* continuous,
    uint32_t n_continuous, float dt, uint32_t action, const float* continuous_action, uint32_t n_continuous_actions) {
    return guarded(__func__, [&] {
        const RecordingUse use(recording);
        if (n_discrete > 0) requireArg(discrete, "discrete (with n_discrete > 0)");
        if (n_continuous > 0) requireArg(continuous, "continuous (with n_continuous > 0)");
        if (n_continuous_actions > 0) requireArg(continuous_action, "continuous_action (with n_continuous_actions > 0)");
        use.recording().addStep(reward, verve::ObservationView{discrete, n_discrete, continuous, n_continuous}, dt, action,
                                verve::ContinuousActionView{continuous_action, n_continuous_actions});
    });
}

VERVE_API verve_result VERVE_CALL verve_recording_add_end_episode(verve_recording* recording, float final_reward) {
    return guarded(__func__, [&] { RecordingUse(recording).recording().addEndEpisode(final_reward); });
}

VERVE_API verve_result VERVE_CALL verve_recording_add_truncation(verve_recording* recording, float reward) {
    return guarded(__func__, [&] { RecordingUse(recording).recording().addTruncation(reward); });
}

VERVE_API verve_result VERVE_CALL verve_recording_get_size(const verve_recording* recording, uint64_t* out_entries) {
    return guarded(__func__, [&] {
        const RecordingUse use(recording);
        requireArg(out_entries, "out_entries");
        *out_entries = use.recording().size();
    });
}

VERVE_API verve_result VERVE_CALL verve_recording_save(const verve_recording* recording, const char* path) {
    return guarded(__func__, [&] {
        std::string bytes;
        {
            const RecordingUse use(recording);
            requireArg(path, "path");
            bytes = verve::recordingToBytes(use.recording());
        }
        verve::writeSaveFile(path, bytes);
    });
}

VERVE_API verve_result VERVE_CALL verve_recording_save_memory(const verve_recording* recording, void* buffer, size_t* size) {
    return guarded(__func__, [&] {
        const RecordingUse use(recording);
        requireArg(size, "size");
        verve::capi::copyOut(verve::recordingToBytes(use.recording()), buffer, *size);
    });
}

VERVE_API verve_result VERVE_CALL verve_recording_load(const char* path, verve_recording** out) {
    return guarded(__func__, [&] {
        requireArg(path, "path");
        requireArg(out, "out");
        handOut(verve::loadRecording(path), out);
    });
}

VERVE_API verve_result VERVE_CALL verve_recording_load_memory(const void* data, size_t size, verve_recording** out) {
    return guarded(__func__, [&] {
        requireArg(data, "data");
        requireArg(out, "out");
        handOut(verve::recordingFromBytes(static_cast<const char*>(data), size), out);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_replay(verve_agent* agent, const verve_recording* recording) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const RecordingUse rec(recording);
        rec.recording().replayInto(use.agent());
    });
}

}  // extern "C"
