// libFuzzer target: verve_agent_load_memory on any bytes. A refused input must leave *out alone
// and set an error; an accepted one must be a working agent that saves and reloads to the same bytes.
#include "exercise.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
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
