// Writes the seed corpus of the load targets: a valid memory save of every kind of agent (discrete,
// continuous, circular, full lattice, planning with each prediction, each curiosity, learning off),
// as XML (<kind>.xml) and binary (<kind>.bin), each after a few updates so its RBFs, weights and model hold real values. Small on purpose:
// libFuzzer mutates small inputs faster. With a second folder, the recording target's seeds too: the
// same steps of some kinds, demonstrated and recorded (<kind>.vrec).
//   verve_fuzz_corpus <dir> [<recordings dir>]
#include <cstdio>
#include <string>
#include <vector>

#include "verve_c.h"

namespace {

struct Kind {
    const char* name;
    void (*shape)(verve_agent_desc&);
};

const Kind kKinds[] = {
    {"discrete", [](verve_agent_desc& d) { d.num_discrete_sensors = 2; d.discrete_sensor_values[0] = 4; d.discrete_sensor_values[1] = 3; }},
    {"continuous", [](verve_agent_desc& d) { d.num_continuous_sensors = 2; }},
    {"circular", [](verve_agent_desc& d) { d.num_continuous_sensors = 2; d.continuous_sensor_circular[0] = 1; }},
    {"mixed", [](verve_agent_desc& d) { d.num_discrete_sensors = 1; d.discrete_sensor_values[0] = 2; d.num_continuous_sensors = 1; }},
    {"full", [](verve_agent_desc& d) { d.num_continuous_sensors = 1; d.rbf_allocation = VERVE_RBF_FULL; }},
    {"planning", [](verve_agent_desc& d) { d.num_discrete_sensors = 1; d.discrete_sensor_values[0] = 5; d.planning = 1; }},
    {"planning-ordinal", [](verve_agent_desc& d) { d.num_discrete_sensors = 1; d.discrete_sensor_values[0] = 5; d.planning = 1; d.discrete_prediction = VERVE_DISCRETE_PREDICTION_ORDINAL; }},
    {"planning-continuous", [](verve_agent_desc& d) { d.num_continuous_sensors = 1; d.planning = 1; }},
    {"novelty", [](verve_agent_desc& d) { d.num_discrete_sensors = 1; d.discrete_sensor_values[0] = 4; d.planning = 1; d.curiosity = VERVE_CURIOSITY_NOVELTY; }},
    {"progress", [](verve_agent_desc& d) { d.num_continuous_sensors = 1; d.planning = 1; d.curiosity = VERVE_CURIOSITY_PROGRESS; }},
    {"no-sensors", [](verve_agent_desc& d) { d.num_actions = 4; }},
    {"groups", [](verve_agent_desc& d) { d.num_continuous_sensors = 6; }},
    {"custom-groups", [](verve_agent_desc& d) {
         d.num_discrete_sensors = 1; d.discrete_sensor_values[0] = 2; d.num_continuous_sensors = 3;
         d.sensor_grouping = VERVE_GROUPING_CUSTOM; d.num_sensor_groups = 2; d.sensor_groups[0] = 0b101; d.sensor_groups[1] = 0b011; }},
    {"branches", [](verve_agent_desc& d) {
         d.num_discrete_sensors = 1; d.discrete_sensor_values[0] = 2; d.num_continuous_sensors = 1;
         d.num_actions = 12; d.num_action_branches = 3; d.action_branches[0] = 3; d.action_branches[1] = 2; d.action_branches[2] = 2; }},
    {"steering", [](verve_agent_desc& d) { d.num_continuous_sensors = 3; d.num_actions = 2; d.num_continuous_actions = 2; }},
};

// A memory save of `object` (an agent, or a recording) by the two-call pattern, written to `path`.
template <typename Object>
bool writeSave(const Object* object, verve_result(VERVE_CALL* save)(const Object*, void*, size_t*), const std::string& path) {
    size_t size = 0;
    if (save(object, nullptr, &size) != VERVE_OK) return false;
    std::vector<char> bytes(size);
    if (save(object, bytes.data(), &size) != VERVE_OK) return false;
    FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) return false;
    const bool ok = std::fwrite(bytes.data(), 1, size, f) == size;
    return std::fclose(f) == 0 && ok;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 && argc != 3) {
        std::fprintf(stderr, "usage: %s <corpus dir> [<recordings dir>]\n", argv[0]);
        return 2;
    }
    for (const Kind& kind : kKinds) {
        verve_agent_desc d;
        verve_agent_desc_default(&d);
        d.resolution = 4;
        d.num_actions = 3;
        kind.shape(d);
        verve_agent* agent = nullptr;
        if (verve_agent_create(&d, &agent) != VERVE_OK) {
            std::fprintf(stderr, "%s: %s\n", kind.name, verve_last_error());
            return 1;
        }
        verve_recording* recording = nullptr;
        if (argc == 3 && !d.planning && verve_recording_create(agent, &recording) != VERVE_OK) {
            std::fprintf(stderr, "%s: %s\n", kind.name, verve_last_error());
            return 1;
        }
        uint32_t action = 0;
        for (int step = 0; step < 12; ++step) {
            const int32_t discrete[2] = {step % 2, step % 3};
            const float x = -0.9f + 0.15f * static_cast<float>(step);
            const float continuous[6] = {x, 0.3f, -x, 0.5f * x, 0.9f, -0.2f};
            const float reward = step % 4 == 3 ? 1.0f : -0.1f;
            if (verve_agent_update(agent, reward, discrete, d.num_discrete_sensors, continuous, d.num_continuous_sensors,
                                   0.1f, &action) != VERVE_OK) {
                std::fprintf(stderr, "%s: %s\n", kind.name, verve_last_error());
                return 1;
            }
        }
        if (recording != nullptr) {
            for (int step = 0; step < 8; ++step) {
                const int32_t discrete[2] = {step % 2, step % 3};
                const float x = 0.2f * static_cast<float>(step) - 0.7f;
                const float continuous[6] = {x, -0.4f, 0.5f * x, 0.1f, -x, 0.6f};
                const float steer[2] = {-x, step % 2 ? 1.0f : -0.5f};  // the teacher's, where the agent has continuous actions
                if (d.num_continuous_actions > 0 && step % 4 != 3) {
                    verve_recording_add_step_continuous(recording, step % 3 == 2 ? 0.5f : 0.0f, discrete, d.num_discrete_sensors,
                                                        continuous, d.num_continuous_sensors, 0.1f,
                                                        static_cast<uint32_t>(step) % d.num_actions, steer,
                                                        static_cast<uint32_t>(d.num_continuous_actions));
                } else {
                    verve_recording_add_step(recording, step % 3 == 2 ? 0.5f : 0.0f, discrete, d.num_discrete_sensors,
                                             continuous, d.num_continuous_sensors, 0.1f, static_cast<uint32_t>(step) % d.num_actions);
                }
                if (step == 4) verve_recording_add_truncation(recording, -0.1f);
            }
            verve_recording_add_end_episode(recording, 1.0f);
            const bool ok = writeSave(recording, verve_recording_save_memory, std::string(argv[2]) + "/" + kind.name + ".vrec");
            verve_recording_destroy(recording);
            if (!ok) {
                std::fprintf(stderr, "%s: cannot write its recording\n", kind.name);
                return 1;
            }
        }
        if (std::string(kind.name) == "discrete") verve_agent_set_learning(agent, 0);
        const std::string stem = std::string(argv[1]) + "/" + kind.name;
        if (!writeSave(agent, verve_agent_save_memory, stem + ".xml") ||
            !writeSave(agent, verve_agent_save_memory_binary, stem + ".bin")) {
            std::fprintf(stderr, "%s: cannot write %s.xml or .bin\n", kind.name, stem.c_str());
            return 1;
        }
        verve_agent_destroy(agent);
    }
    return 0;
}
