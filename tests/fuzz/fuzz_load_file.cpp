// libFuzzer target: verve_agent_load on a file holding any bytes (the path the file API takes,
// with its own size checks and reads), then a save to a file and a reload.
#include <cstdio>
#include <string>

#include <unistd.h>

#include "exercise.hpp"

namespace {

std::string scratchPath(const char* name) {
    static const std::string dir = [] {
        char tmpl[] = "/tmp/verve-fuzz-XXXXXX";
        const char* made = mkdtemp(tmpl);
        if (made == nullptr) std::abort();
        return std::string(made);
    }();
    return dir + "/" + name;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string input = scratchPath("input.xml");
    FILE* f = std::fopen(input.c_str(), "wb");
    if (f == nullptr) std::abort();
    if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
    std::fclose(f);

    verve_agent* agent = nullptr;
    if (verve_agent_load(input.c_str(), &agent) != VERVE_OK) {
        VERVE_FUZZ_CHECK(agent == nullptr && verve_last_error()[0] != '\0');
        return 0;
    }
    FuzzedDataProvider in(data, size);
    verve_fuzz::play(agent, in, 4);
    const std::string saved = scratchPath("saved.xml");
    VERVE_FUZZ_CHECK(verve_agent_save(agent, saved.c_str()) == VERVE_OK);
    verve_agent* again = nullptr;
    VERVE_FUZZ_CHECK(verve_agent_load(saved.c_str(), &again) == VERVE_OK);
    verve_agent_destroy(again);
    verve_agent_destroy(agent);
    return 0;
}
