// libFuzzer target: verve_recording_load_memory on any bytes (docs/teaching.md, "Recordings"). A
// refused input must leave *out alone and set an error; an accepted one must save to bytes that load
// back to the same bytes, and replay into an agent: refused and unchanged when the agent's sensors
// and actions are not the recording's (the seeds' "mixed" shape is), else a working agent; and the
// same into an agent with continuous actions (the "steering" seed's shape, whose steps carry them).
#include "exercise.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    verve_recording* sentinel = reinterpret_cast<verve_recording*>(uintptr_t{0x1});
    verve_recording* recording = sentinel;
    if (verve_recording_load_memory(data, size, &recording) != VERVE_OK) {
        VERVE_FUZZ_CHECK(recording == sentinel && verve_last_error()[0] != '\0');
        return 0;
    }
    const std::vector<char> bytes = verve_fuzz::savedBytes(recording, verve_recording_save_memory);
    verve_recording* again = nullptr;
    VERVE_FUZZ_CHECK(verve_recording_load_memory(bytes.data(), bytes.size(), &again) == VERVE_OK);
    VERVE_FUZZ_CHECK(verve_fuzz::savedBytes(again, verve_recording_save_memory) == bytes);
    verve_recording_destroy(again);

    for (int shape = 0; shape < 2; ++shape) {
        verve_agent_desc d;
        verve_agent_desc_default(&d);
        d.resolution = 4;
        if (shape == 0) {  // "mixed"
            d.num_actions = 3;
            d.num_discrete_sensors = 1;
            d.discrete_sensor_values[0] = 2;
            d.num_continuous_sensors = 1;
        } else {  // "steering"
            d.num_actions = 2;
            d.num_continuous_sensors = 3;
            d.num_continuous_actions = 2;
        }
        verve_agent* agent = nullptr;
        VERVE_FUZZ_CHECK(verve_agent_create(&d, &agent) == VERVE_OK);
        const std::vector<char> before = verve_fuzz::savedBytes(agent, verve_agent_save_memory_binary);
        if (verve_agent_replay(agent, recording) == VERVE_OK) {
            verve_agent_destroy(verve_fuzz::roundTrip(agent));
        } else {
            VERVE_FUZZ_CHECK(verve_fuzz::savedBytes(agent, verve_agent_save_memory_binary) == before);
        }
        verve_agent_destroy(agent);
    }
    verve_recording_destroy(recording);
    return 0;
}
