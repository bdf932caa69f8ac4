// libFuzzer target: a fuzzed descriptor, then a fuzzed sequence of C ABI calls with good and bad
// arguments. Checks the promises of verve_c.h: no crash, hang or leak; a failed call sets an error
// and changes nothing that the read-outs can see; a memory save reloads to the same bytes.
#include <vector>

#include "exercise.hpp"

namespace {

using verve_fuzz::anyCount;
using verve_fuzz::anyFloat;

// Everything a failed call must leave as it was, as the read-outs report it.
struct Visible {
    verve_agent_stats stats{};
    int learning = -1;
    bool operator==(const Visible& o) const {
        return stats.steps == o.stats.steps && stats.rbf_count == o.stats.rbf_count &&
               stats.live_traces == o.stats.live_traces && learning == o.learning;
    }
};

Visible visible(const verve_agent* agent) {
    Visible v;
    v.stats.struct_size = sizeof v.stats;
    VERVE_FUZZ_CHECK(verve_agent_get_stats(agent, &v.stats) == VERVE_OK);
    VERVE_FUZZ_CHECK(verve_agent_get_learning(agent, &v.learning) == VERVE_OK);
    return v;
}

void sampleValues(const verve_agent* agent, const verve_agent_desc& d, FuzzedDataProvider& in) {
    verve_value_axis axes[3];
    const uint32_t nAxes = in.ConsumeIntegralInRange<uint32_t>(0, 3);
    for (verve_value_axis& a : axes) {
        a.kind = in.ConsumeIntegralInRange<uint32_t>(0, 2);
        a.index = in.ConsumeIntegralInRange<uint32_t>(0, 4);
        a.samples = in.ConsumeBool() ? in.ConsumeIntegralInRange<uint32_t>(0, 40) : anyCount(in, 64);
    }
    const verve_fuzz::Observation base = verve_fuzz::anyObservation(in, d);
    std::vector<float> out(in.ConsumeIntegralInRange<size_t>(0, 2048));
    const uint32_t outCount = in.ConsumeBool() ? static_cast<uint32_t>(out.size()) : anyCount(in, 2048);
    // A count larger than the buffer would be the host's own overflow: keep it within the buffer.
    const uint32_t safeCount = outCount <= out.size() ? outCount : static_cast<uint32_t>(out.size());
    verve_agent_sample_values(agent, axes, nAxes, base.discrete, base.numDiscrete, base.continuous, base.numContinuous,
                              out.empty() ? nullptr : out.data(), safeCount);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider in(data, size);
    const verve_agent_desc desc = verve_fuzz::anyDescriptor(in);
    verve_agent* agent = nullptr;
    if (verve_agent_create(&desc, &agent) != VERVE_OK) {
        VERVE_FUZZ_CHECK(agent == nullptr && verve_last_error()[0] != '\0');
        return 0;
    }
    verve_agent_desc d;
    verve_agent_desc_init(&d, sizeof d);
    VERVE_FUZZ_CHECK(verve_agent_get_desc(agent, &d) == VERVE_OK);

    size_t saveBytes = 0;  // skips saves past verve_fuzz::kSaveBytesPerInput
    for (int call = 0; call < 64 && in.remaining_bytes() > 0; ++call) {
        const Visible before = visible(agent);
        verve_result r = VERVE_OK;
        bool changes = false;  // a successful call of this kind may change what visible() reports
        switch (in.ConsumeIntegralInRange<int>(0, 20)) {
            case 0:
            case 1:
            case 2: {
                const verve_fuzz::Observation o = verve_fuzz::anyObservation(in, d);
                uint32_t action = 0;
                r = verve_agent_update(agent, anyFloat(in, -1.5f, 1.5f), in.ConsumeBool() ? o.discrete : nullptr,
                                       o.numDiscrete, in.ConsumeIntegralInRange<int>(0, 15) ? o.continuous : nullptr,
                                       o.numContinuous, anyFloat(in, 0.001f, 1.0f), &action);
                if (r == VERVE_OK) VERVE_FUZZ_CHECK(action < d.num_actions);
                changes = true;
                break;
            }
            case 3:
                r = verve_agent_end_episode(agent, anyFloat(in, -1.5f, 1.5f));
                changes = true;
                break;
            case 4:
                r = verve_agent_reset_short_term_memory(agent);
                changes = true;
                break;
            case 5:
                r = verve_agent_set_learning(agent, in.ConsumeIntegralInRange<int>(-1, 2));
                changes = true;
                break;
            case 6: {
                float value = 0.0f;
                uint32_t count = 0;
                VERVE_FUZZ_CHECK(verve_agent_get_value(agent, &value) == VERVE_OK);
                VERVE_FUZZ_CHECK(verve_agent_get_td_error(agent, &value) == VERVE_OK);
                VERVE_FUZZ_CHECK(verve_agent_get_rbf_count(agent, &count) == VERVE_OK);
                verve_agent_stats stats{};
                stats.struct_size = in.ConsumeBool() ? sizeof stats : in.ConsumeIntegralInRange<uint32_t>(0, 2 * sizeof stats);
                r = verve_agent_get_stats(agent, &stats);
                break;
            }
            case 7:
                sampleValues(agent, d, in);
                break;
            case 8: {
                if (saveBytes >= verve_fuzz::kSaveBytesPerInput) break;
                verve_agent* copy = verve_fuzz::roundTrip(agent, &saveBytes);
                if (copy != nullptr && in.ConsumeBool()) {  // carry on with the reloaded copy
                    verve_agent_destroy(agent);
                    agent = copy;
                    changes = true;  // a reload starts a fresh trial: traces are not saved
                } else {
                    verve_agent_destroy(copy);
                }
                break;
            }
            case 9: {
                if (saveBytes >= verve_fuzz::kSaveBytesPerInput) break;
                size_t size = in.ConsumeIntegralInRange<size_t>(0, 4096);
                std::vector<char> small(size);
                r = verve_agent_save_memory(agent, small.empty() ? nullptr : small.data(), &size);
                saveBytes += size;  // the size the save needed (written back when the buffer was too small)
                break;
            }
            case 10: {
                verve_agent_desc out;
                out.struct_size = in.ConsumeBool() ? sizeof out : in.ConsumeIntegral<uint32_t>();
                r = verve_agent_get_desc(agent, &out);
                break;
            }
            case 12: {  // an update with an action mask: masked actions are never chosen
                const verve_fuzz::Observation o = verve_fuzz::anyObservation(in, d);
                uint8_t mask[64];
                for (uint8_t& m : mask) m = in.ConsumeIntegralInRange<int>(0, 15) == 0 ? in.ConsumeIntegral<uint8_t>() : in.ConsumeIntegralInRange<uint8_t>(0, 1);
                const uint32_t n = in.ConsumeBool() ? verve_fuzz::actionChoices(d) : in.ConsumeIntegralInRange<uint32_t>(0, 64);
                uint32_t action = 0;
                r = verve_agent_update_masked(agent, anyFloat(in, -1.5f, 1.5f), o.discrete, o.numDiscrete, o.continuous,
                                              o.numContinuous, anyFloat(in, 0.001f, 1.0f), n <= 64 ? mask : nullptr, n, &action);
                if (r == VERVE_OK) VERVE_FUZZ_CHECK(action < d.num_actions && n <= 64 && verve_fuzz::maskAllows(d, mask, action));
                changes = true;
                break;
            }
            case 16: {  // a demonstrated step: any action, any mask (or none); a refusal changes nothing
                const verve_fuzz::Observation o = verve_fuzz::anyObservation(in, d);
                uint8_t mask[64];
                for (uint8_t& m : mask) m = in.ConsumeIntegralInRange<int>(0, 15) == 0 ? in.ConsumeIntegral<uint8_t>() : in.ConsumeIntegralInRange<uint8_t>(0, 1);
                const bool masked = in.ConsumeBool();
                const uint32_t n = masked ? (in.ConsumeBool() ? verve_fuzz::actionChoices(d) : in.ConsumeIntegralInRange<uint32_t>(0, 64)) : 0;
                const uint32_t action = in.ConsumeBool() ? in.ConsumeIntegralInRange<uint32_t>(0, d.num_actions - 1) : in.ConsumeIntegral<uint32_t>();
                r = verve_agent_update_demonstrated(agent, anyFloat(in, -1.5f, 1.5f), o.discrete, o.numDiscrete, o.continuous,
                                                    o.numContinuous, anyFloat(in, 0.001f, 1.0f), masked ? mask : nullptr, n, action);
                if (r == VERVE_OK) VERVE_FUZZ_CHECK(action < d.num_actions && (!masked || (n <= 64 && verve_fuzz::maskAllows(d, mask, action))));
                changes = true;
                break;
            }
            case 20: {  // a demonstrated step with the teacher's continuous actions: right count, each in
                        // [-1, 1], else refused (changing nothing); accepted values are played back
                const verve_fuzz::Observation o = verve_fuzz::anyObservation(in, d);
                const uint32_t n = static_cast<uint32_t>(d.num_continuous_actions);
                const uint32_t count = in.ConsumeBool() ? n : in.ConsumeIntegralInRange<uint32_t>(0, 10);
                std::vector<float> values(count);
                for (float& v : values) v = anyFloat(in, -1.0f, 1.0f);
                const uint32_t action = in.ConsumeBool() ? in.ConsumeIntegralInRange<uint32_t>(0, d.num_actions - 1) : in.ConsumeIntegral<uint32_t>();
                r = verve_agent_update_demonstrated_continuous(agent, anyFloat(in, -1.5f, 1.5f), o.discrete, o.numDiscrete,
                                                               o.continuous, o.numContinuous, anyFloat(in, 0.001f, 1.0f), nullptr, 0,
                                                               action, values.empty() ? nullptr : values.data(), count);
                if (r == VERVE_OK) {
                    VERVE_FUZZ_CHECK(count == n && action < d.num_actions);
                    std::vector<float> played(n);
                    if (n > 0) {
                        VERVE_FUZZ_CHECK(verve_agent_get_continuous_action(agent, played.data(), n) == VERVE_OK);
                        for (uint32_t k = 0; k < n; ++k) VERVE_FUZZ_CHECK(values[k] >= -1.0f && values[k] <= 1.0f && played[k] == values[k]);
                    }
                }
                changes = true;
                break;
            }
            case 17:  // a teacher's judgement of the acts before it (NaN and beyond [-1, 1] refused)
                r = verve_agent_teach(agent, anyFloat(in, -1.5f, 1.5f));
                changes = true;
                break;
            case 13:
                r = verve_agent_truncate_episode(agent, anyFloat(in, -1.5f, 1.5f));
                changes = true;
                break;
            case 14:
                r = verve_agent_set_action_selection(agent, in.ConsumeIntegralInRange<uint32_t>(0, 2));
                break;
            case 15: {  // probabilities sum to 1 over the agent's actions (over each branch's choices)
                std::vector<float> p(in.ConsumeBool() ? verve_fuzz::actionChoices(d) : in.ConsumeIntegralInRange<uint32_t>(0, 16));
                r = verve_agent_get_action_probabilities(agent, p.empty() ? nullptr : p.data(), static_cast<uint32_t>(p.size()));
                if (r == VERVE_OK) {
                    const uint32_t branches = d.num_action_branches == 0 ? 1 : d.num_action_branches;
                    for (uint32_t b = 0, at = 0; b < branches; ++b) {
                        const uint32_t size = d.num_action_branches == 0 ? d.num_actions : d.action_branches[b];
                        double sum = 0.0;
                        for (uint32_t k = 0; k < size; ++k) sum += p[at + k];
                        VERVE_FUZZ_CHECK(sum > 0.99 && sum < 1.01);
                        at += size;
                    }
                }
                break;
            }
            case 18: {  // a combined action split and joined back; anything out of range refused
                uint32_t choices[VERVE_MAX_ACTION_BRANCHES + 2] = {};
                const uint32_t branches = d.num_action_branches == 0 ? 1 : d.num_action_branches;
                const uint32_t n = in.ConsumeBool() ? branches : in.ConsumeIntegralInRange<uint32_t>(0, VERVE_MAX_ACTION_BRANCHES + 2);
                const uint32_t action = in.ConsumeBool() ? in.ConsumeIntegralInRange<uint32_t>(0, d.num_actions - 1) : in.ConsumeIntegral<uint32_t>();
                // Random choices joined first: the split's result, and its message when refused,
                // must be the last call's (a later successful call clears the message).
                if (in.ConsumeBool()) {
                    for (uint32_t& c : choices) c = in.ConsumeIntegralInRange<uint32_t>(0, 5);
                    uint32_t joined = UINT32_MAX;
                    if (verve_agent_join_action(agent, choices, n, &joined) == VERVE_OK) VERVE_FUZZ_CHECK(joined < d.num_actions);
                }
                r = verve_agent_split_action(agent, action, choices, n);
                VERVE_FUZZ_CHECK((r == VERVE_OK) == (n == branches && action < d.num_actions));
                if (r == VERVE_OK) {
                    uint32_t back = UINT32_MAX;
                    VERVE_FUZZ_CHECK(verve_agent_join_action(agent, choices, n, &back) == VERVE_OK && back == action);
                }
                break;
            }
            case 19: {  // the continuous actions: their count or refused, each within [-1, 1]
                const uint32_t n = static_cast<uint32_t>(d.num_continuous_actions);
                std::vector<float> v(in.ConsumeBool() ? n : in.ConsumeIntegralInRange<uint32_t>(0, 10), 2.0f);
                r = verve_agent_get_continuous_action(agent, v.empty() ? nullptr : v.data(), static_cast<uint32_t>(v.size()));
                VERVE_FUZZ_CHECK((r == VERVE_OK) == (!v.empty() && v.size() == n));  // NULL out is refused
                if (r == VERVE_OK) {
                    for (float x : v) VERVE_FUZZ_CHECK(x >= -1.0f && x <= 1.0f);
                }
                break;
            }
            case 11: {
                // NULL arguments everywhere must be refused, never dereferenced.
                VERVE_FUZZ_CHECK(verve_agent_update(agent, 0.0f, nullptr, 0, nullptr, 0, 0.1f, nullptr) != VERVE_OK);
                VERVE_FUZZ_CHECK(verve_agent_get_stats(agent, nullptr) != VERVE_OK);
                VERVE_FUZZ_CHECK(verve_agent_save_memory(agent, nullptr, nullptr) != VERVE_OK);
                VERVE_FUZZ_CHECK(verve_agent_update(nullptr, 0.0f, nullptr, 0, nullptr, 0, 0.1f, nullptr) != VERVE_OK);
                break;
            }
        }
        if (r != VERVE_OK) {
            VERVE_FUZZ_CHECK(verve_last_error()[0] != '\0');
            VERVE_FUZZ_CHECK(visible(agent) == before);
        } else if (!changes) {
            VERVE_FUZZ_CHECK(visible(agent) == before);
        }
    }
    verve_agent_destroy(agent);
    return 0;
}
