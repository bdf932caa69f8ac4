// libFuzzer target: verve_agent_load_memory and verve_brain_load_memory on any bytes. A refused
// input must leave *out alone and set an error; an accepted one must be a working agent (or brain)
// that saves and reloads to the same bytes.
#include <cstring>

#include "exercise.hpp"

namespace {

// The same bytes as a brain's save (an agent's save loads as a brain): refused with an error and
// *out alone, or a brain whose save round-trips (verve_fuzz::brainRoundTrip).
void loadAsBrain(const uint8_t* data, size_t size) {
    verve_brain* sentinel = reinterpret_cast<verve_brain*>(uintptr_t{0x1});
    verve_brain* brain = sentinel;
    if (verve_brain_load_memory(data, size, &brain) != VERVE_OK) {
        VERVE_FUZZ_CHECK(brain == sentinel && verve_last_error()[0] != '\0');
        return;
    }
    const bool binary = size >= 8 && std::memcmp(data, "VERVEBIN", 8) == 0;  // saved as it was given
    verve_fuzz::brainRoundTrip(brain, binary);
    verve_brain_destroy(brain);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    loadAsBrain(data, size);
    verve_agent* sentinel = reinterpret_cast<verve_agent*>(uintptr_t{0x1});
    verve_agent* agent = sentinel;
    const verve_result r = verve_agent_load_memory(data, size, &agent);
    if (r != VERVE_OK) {
        VERVE_FUZZ_CHECK(agent == sentinel && verve_last_error()[0] != '\0');
        return 0;
    }
    // Drive the loaded agent with bytes derived from the input itself.
    FuzzedDataProvider in(data, size);
    verve_fuzz::play(agent, in, 8);
    verve_agent_destroy(verve_fuzz::roundTrip(agent));
    verve_agent_destroy(agent);
    return 0;
}
