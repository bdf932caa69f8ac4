// What every fuzz target does with an agent it managed to create or load: the calls a game makes
// every frame, driven by the fuzzer's remaining bytes, checking the invariants the C ABI promises.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fuzz_input.hpp"

namespace verve_fuzz {

// The library broke a promise: say which, and abort so libFuzzer records the input.
#define VERVE_FUZZ_CHECK(condition)                                                             \
    do {                                                                                        \
        if (!(condition)) {                                                                     \
            std::fprintf(stderr, "%s:%d: the check failed: %s\n", __FILE__, __LINE__, #condition); \
            std::abort();                                                                       \
        }                                                                                       \
    } while (0)

// What one input may spend on saves, in bytes of save text: a save takes time in proportion to
// its size (a round trip of the largest agent the fuzz descriptors allow, ~4 MB of XML, takes
// ~0.25 s under ASan), and a sequence of calls could ask for one at nearly every call; past this,
// the call-sequence targets skip their saves, so an input over the 1 s limit is a hang.
constexpr size_t kSaveBytesPerInput = size_t{8} << 20;

// A save to memory by the two-call pattern (save: verve_agent_save_memory or a kin, for an agent
// or a brain); both calls must succeed and agree on the size.
template <typename Object>
std::vector<char> savedBytes(const Object* object, verve_result(VERVE_CALL* save)(const Object*, void*, size_t*)) {
    size_t size = 0;
    VERVE_FUZZ_CHECK(save(object, nullptr, &size) == VERVE_OK);
    std::vector<char> bytes(size);
    size_t written = size;
    VERVE_FUZZ_CHECK(save(object, bytes.data(), &written) == VERVE_OK && written == size);
    return bytes;
}

// A brain's save (XML or binary) loads as a brain that saves the same bytes, and as an agent.
// Adds its cost to *work as roundTrip does.
inline void brainRoundTrip(const verve_brain* brain, bool binary, size_t* work = nullptr) {
    auto save = binary ? verve_brain_save_memory_binary : verve_brain_save_memory;
    const std::vector<char> bytes = savedBytes(brain, save);
    if (work != nullptr) *work += 5 * bytes.size();
    verve_brain* copy = nullptr;
    VERVE_FUZZ_CHECK(verve_brain_load_memory(bytes.data(), bytes.size(), &copy) == VERVE_OK);
    VERVE_FUZZ_CHECK(savedBytes(static_cast<const verve_brain*>(copy), save) == bytes);
    verve_agent* asAgent = nullptr;
    VERVE_FUZZ_CHECK(verve_agent_load_memory(bytes.data(), bytes.size(), &asAgent) == VERVE_OK);
    verve_agent_destroy(asAgent);
    verve_brain_destroy(copy);
}

// Saves to memory with the two-call pattern, loads the bytes back and checks the copy saves
// to the same bytes. Returns the loaded copy (or NULL if the save was refused). Adds its cost to
// *work, in bytes of save text: the size query's, then four more sizes for the saves and the load.
inline verve_agent* roundTrip(const verve_agent* agent, size_t* work = nullptr) {
    size_t size = 0;
    const verve_result sized = verve_agent_save_memory(agent, nullptr, &size);
    if (work != nullptr) *work += size;
    if (sized != VERVE_OK) return nullptr;
    if (work != nullptr) *work += 4 * size;
    std::vector<char> bytes(size);
    size_t written = size;
    VERVE_FUZZ_CHECK(verve_agent_save_memory(agent, bytes.data(), &written) == VERVE_OK && written == size);
    verve_agent* copy = nullptr;
    VERVE_FUZZ_CHECK(verve_agent_load_memory(bytes.data(), bytes.size(), &copy) == VERVE_OK && copy != nullptr);
    VERVE_FUZZ_CHECK(savedBytes(static_cast<const verve_agent*>(copy), verve_agent_save_memory) == bytes);
    return copy;
}

// A bounded number of updates with the agent's own shape (and some bad inputs, which must be
// refused without changing the step count).
inline void play(verve_agent* agent, FuzzedDataProvider& in, int maxSteps) {
    verve_agent_desc d;
    verve_agent_desc_init(&d, sizeof d);
    VERVE_FUZZ_CHECK(verve_agent_get_desc(agent, &d) == VERVE_OK);
    const int steps = in.ConsumeIntegralInRange<int>(0, maxSteps);
    for (int i = 0; i < steps && in.remaining_bytes() > 0; ++i) {
        const Observation o = anyObservation(in, d);
        verve_agent_stats before{};
        before.struct_size = sizeof before;
        VERVE_FUZZ_CHECK(verve_agent_get_stats(agent, &before) == VERVE_OK);
        uint32_t action = UINT32_MAX;
        const float reward = anyFloat(in, -1.5f, 1.5f);
        const float dt = anyFloat(in, 0.001f, 1.0f);
        const verve_result r = verve_agent_update(agent, reward, o.discrete, o.numDiscrete, o.continuous, o.numContinuous, dt, &action);
        VERVE_FUZZ_CHECK((r == VERVE_OK) == (verve_last_error()[0] == '\0'));  // read before the next call clears it
        verve_agent_stats after{};
        after.struct_size = sizeof after;
        VERVE_FUZZ_CHECK(verve_agent_get_stats(agent, &after) == VERVE_OK);
        if (r == VERVE_OK) {
            VERVE_FUZZ_CHECK(action < d.num_actions && after.steps == before.steps + 1);
        } else {
            VERVE_FUZZ_CHECK(after.steps == before.steps);
        }
        if (in.ConsumeIntegralInRange<int>(0, 15) == 0) verve_agent_end_episode(agent, anyFloat(in, -1.0f, 1.0f));
    }
}

}  // namespace verve_fuzz
