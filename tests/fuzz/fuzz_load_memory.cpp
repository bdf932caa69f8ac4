// libFuzzer target: verve_agent_load_memory and verve_brain_load_memory on any bytes. A refused
// input must leave *out alone and set an error; an accepted one must be a working agent (or brain)
// that saves and reloads to the same bytes.
#include <cstring>
#include <vector>

#include "exercise.hpp"

namespace {

// The same bytes as a brain's save (an agent's save loads as a brain): refused with an error and
// *out alone, or a brain that saves, in the format it was given, bytes that load to the same save.
void loadAsBrain(const uint8_t* data, size_t size) {
    verve_brain* sentinel = reinterpret_cast<verve_brain*>(uintptr_t{0x1});
    verve_brain* brain = sentinel;
    if (verve_brain_load_memory(data, size, &brain) != VERVE_OK) {
        VERVE_FUZZ_CHECK(brain == sentinel && verve_last_error()[0] != '\0');
        return;
    }
    const bool binary = size >= 8 && std::memcmp(data, "VERVEBIN", 8) == 0;
    auto save = binary ? verve_brain_save_memory_binary : verve_brain_save_memory;
    size_t bytes = 0;
    VERVE_FUZZ_CHECK(save(brain, nullptr, &bytes) == VERVE_OK);
    std::vector<char> first(bytes);
    VERVE_FUZZ_CHECK(save(brain, first.data(), &bytes) == VERVE_OK);
    verve_brain* copy = nullptr;
    VERVE_FUZZ_CHECK(verve_brain_load_memory(first.data(), first.size(), &copy) == VERVE_OK);
    size_t again = 0;
    VERVE_FUZZ_CHECK(save(copy, nullptr, &again) == VERVE_OK && again == bytes);
    std::vector<char> second(again);
    VERVE_FUZZ_CHECK(save(copy, second.data(), &again) == VERVE_OK && second == first);
    verve_brain_destroy(copy);
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
