// libFuzzer target: crowds. Fuzzed descriptors make brains and agents of their own; a crowd lists
// bodies and agents in any order, repeats included, and is stepped by verve_batch_update (or, with
// demonstrated actions, verve_batch_update_demonstrated, or with continuous ones too,
// verve_batch_update_demonstrated_continuous) on
// Verve's pool or on a host's job system (ranges run in reverse), with packed or spaced
// observations, bad values, wrong totals and NULL entries, between bodies made, handles destroyed
// and brains saved. The same calls run on a twin world built alike, its batch steps done by a batch
// of one worker. Checks the promises of verve_c.h: a refused batch changes no member and sets an
// error; an accepted one acts the same on any number of threads (the same verdicts and actions,
// and the same saves at the end); a brain's save reloads, as a brain and as an agent, to the same
// bytes. (That separate agents act as their single updates do, tests/capi/crowd_test.cpp checks.)
#include <algorithm>
#include <cstdint>
#include <vector>

#include "exercise.hpp"

namespace {

using verve_fuzz::anyFloat;

constexpr size_t kMaxMembers = 10;

// A host job system on the calling thread: the task's ranges in reverse order, each given the
// worker index its range would have on a host with three workers.
void* VERVE_CALL enqueueReversed(verve_task_fn task, uint32_t count, uint32_t minRange, void* taskContext, void*) {
    const uint32_t range = std::max<uint32_t>(minRange, 1);
    const uint32_t ranges = (count + range - 1) / range;
    for (uint32_t r = ranges; r-- > 0;) task(r * range, std::min(count, (r + 1) * range), r % 3, taskContext);
    return nullptr;  // ran inline: finish_task is not called
}
void VERVE_CALL finishNothing(void*, void*) {}

// A batch of `workers` on Verve's pool, or with the host's reversed ranges above.
verve_batch* makeBatch(uint32_t workers, bool host) {
    verve_batch_desc d;
    verve_batch_desc_default(&d);
    d.worker_count = workers;
    if (host) {
        d.enqueue_task = enqueueReversed;
        d.finish_task = finishNothing;
    }
    verve_batch* b = nullptr;
    VERVE_FUZZ_CHECK(verve_batch_create(&d, &b) == VERVE_OK);
    return b;
}

// Made once: starting threads per input would be most of the run's time. The twin's has one worker.
verve_batch* twinBatch() {
    static verve_batch* const one = makeBatch(1, false);
    return one;
}

verve_batch* batch(bool host) {
    static verve_batch* const pool = makeBatch(2, false);
    static verve_batch* const hosted = makeBatch(3, true);
    return host ? hosted : pool;
}

// A fuzzed descriptor with a crowd's budget: every update runs up to 12 times per step in each
// of two worlds, so the planning steps per update (up to 65,536 in fuzz_calls' descriptors, whose
// 6 s inputs here were a host's request, not a hang) are held to 32 and the RBFs to a tenth.
verve_agent_desc crowdDescriptor(FuzzedDataProvider& in) {
    verve_agent_desc d = verve_fuzz::anyDescriptor(in);
    d.max_planning_steps = std::min<uint32_t>(d.max_planning_steps, 32);
    d.max_rbfs = std::max<uint64_t>(d.max_rbfs / 10, 1);
    return d;
}

uint64_t stepsOf(const verve_agent* agent) {
    verve_agent_stats s{};
    s.struct_size = sizeof s;
    VERVE_FUZZ_CHECK(verve_agent_get_stats(agent, &s) == VERVE_OK);
    return s.steps;
}


// Brains and members (bodies or agents of their own); one of two twins.
struct World {
    std::vector<verve_brain*> brains;
    std::vector<verve_agent*> members;

    ~World() {
        for (verve_agent* a : members) verve_agent_destroy(a);
        for (verve_brain* b : brains) verve_brain_destroy(b);
    }
    std::vector<uint64_t> steps() const {
        std::vector<uint64_t> s;
        for (const verve_agent* a : members) s.push_back(stepsOf(a));
        return s;
    }
};

// One batch step's arguments, read from the input once for both twins.
struct Step {
    std::vector<size_t> entries;  // member indices; kMaxMembers stands for a NULL entry
    std::vector<float> rewards;
    std::vector<int32_t> discrete;
    std::vector<float> continuous;
    std::vector<uint32_t> discreteOffsets, continuousOffsets;  // empty: packed
    uint32_t discreteTotal = 0, continuousTotal = 0;
    std::vector<uint32_t> numDiscrete, numContinuous;  // each entry's sensors (its shape, whatever was packed)
    float dt = 0.1f;
    bool host = false;
    // Through verve_batch_update_demonstrated: per entry an action the host took (mostly one the
    // agent has), or VERVE_AGENT_CHOOSES.
    bool demonstrates = false;
    std::vector<uint32_t> demonstrated;
    // ... and now and then through verve_batch_update_demonstrated_continuous: each entry's
    // continuous actions (its count, mostly in [-1, 1]), packed or at offsets.
    bool showsContinuous = false;
    std::vector<float> shownContinuous;
    std::vector<uint32_t> shownOffsets;
    uint32_t shownTotal = 0;
};

// Mostly what a working game passes, so that batches are accepted and compared with the twin's
// batch; now and then anything (NaN, infinities, huge, wrong counts), so that refusals are.
float mostlyGood(FuzzedDataProvider& in, float lo, float hi) {
    return in.ConsumeIntegralInRange<int>(0, 15) == 0 ? anyFloat(in, lo, hi) : in.ConsumeFloatingPointInRange<float>(lo, hi);
}

verve_fuzz::Observation mostlyGood(FuzzedDataProvider& in, const verve_agent_desc& d) {
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) return verve_fuzz::anyObservation(in, d);
    verve_fuzz::Observation o;
    o.numDiscrete = d.num_discrete_sensors;
    o.numContinuous = d.num_continuous_sensors;
    for (uint32_t i = 0; i < o.numDiscrete; ++i) {
        o.discrete[i] = static_cast<int32_t>(in.ConsumeIntegralInRange<uint32_t>(0, verve_fuzz::discreteValues(d, i) - 1));
    }
    for (uint32_t i = 0; i < o.numContinuous; ++i) o.continuous[i] = in.ConsumeFloatingPointInRange<float>(-1.2f, 1.2f);
    return o;
}

Step readStep(FuzzedDataProvider& in, const World& world) {
    Step s;
    s.dt = mostlyGood(in, 0.001f, 1.0f);
    s.host = in.ConsumeBool();
    const size_t n = in.ConsumeIntegralInRange<size_t>(0, 12);
    const bool spaced = in.ConsumeBool();
    s.demonstrates = in.ConsumeIntegralInRange<int>(0, 3) == 0;
    s.showsContinuous = s.demonstrates && in.ConsumeBool();
    for (size_t i = 0; i < n && !world.members.empty(); ++i) {
        const bool null = in.ConsumeIntegralInRange<int>(0, 31) == 0;
        const size_t m = null ? kMaxMembers : in.ConsumeIntegralInRange<size_t>(0, world.members.size() - 1);
        verve_agent_desc d;
        verve_agent_desc_init(&d, sizeof d);
        if (!null) VERVE_FUZZ_CHECK(verve_agent_get_desc(world.members[m], &d) == VERVE_OK);
        const verve_fuzz::Observation o = mostlyGood(in, d);
        s.entries.push_back(m);
        s.numDiscrete.push_back(d.num_discrete_sensors);
        s.numContinuous.push_back(d.num_continuous_sensors);
        s.rewards.push_back(mostlyGood(in, -1.5f, 1.5f));
        if (s.demonstrates) {
            const int kind = in.ConsumeIntegralInRange<int>(0, 15);
            s.demonstrated.push_back(kind == 0 ? in.ConsumeIntegral<uint32_t>()
                                     : kind < 6 ? VERVE_AGENT_CHOOSES
                                                : in.ConsumeIntegralInRange<uint32_t>(0, d.num_actions - 1));
        }
        if (s.showsContinuous) {
            if (spaced) {
                s.shownContinuous.resize(s.shownContinuous.size() + in.ConsumeIntegralInRange<size_t>(0, 2), 9.0f);
                s.shownOffsets.push_back(static_cast<uint32_t>(s.shownContinuous.size()));
            }
            for (uint64_t k = 0; k < std::min<uint64_t>(d.num_continuous_actions, VERVE_MAX_CONTINUOUS_ACTIONS); ++k) {
                s.shownContinuous.push_back(mostlyGood(in, -1.0f, 1.0f));
            }
        }
        if (spaced) {  // a gap before each agent's values, as in a struct of arrays with other fields
            s.discrete.resize(s.discrete.size() + in.ConsumeIntegralInRange<size_t>(0, 2), -7);
            s.continuous.resize(s.continuous.size() + in.ConsumeIntegralInRange<size_t>(0, 2), -7.0f);
            s.discreteOffsets.push_back(static_cast<uint32_t>(s.discrete.size()));
            s.continuousOffsets.push_back(static_cast<uint32_t>(s.continuous.size()));
        }
        s.discrete.insert(s.discrete.end(), o.discrete, o.discrete + std::min<uint32_t>(o.numDiscrete, VERVE_MAX_SENSORS + 4));
        s.continuous.insert(s.continuous.end(), o.continuous,
                            o.continuous + std::min<uint32_t>(o.numContinuous, VERVE_MAX_SENSORS + 4));
    }
    s.discreteTotal = static_cast<uint32_t>(s.discrete.size());
    s.continuousTotal = static_cast<uint32_t>(s.continuous.size());
    switch (in.ConsumeIntegralInRange<int>(0, 15)) {  // now and then a longer buffer, a short total, an offset anywhere
        case 0: s.discreteTotal += in.ConsumeIntegralInRange<uint32_t>(1, 3); break;
        case 1: s.continuousTotal = in.ConsumeIntegralInRange<uint32_t>(0, s.continuousTotal); break;
        case 2:
            if (!s.continuousOffsets.empty()) s.continuousOffsets.back() = in.ConsumeIntegral<uint32_t>();
            break;
        default: break;
    }
    s.shownTotal = static_cast<uint32_t>(s.shownContinuous.size());
    if (s.showsContinuous && in.ConsumeIntegralInRange<int>(0, 7) == 0) {
        s.shownTotal = in.ConsumeIntegralInRange<uint32_t>(0, s.shownTotal);  // a short total
    }
    // The arrays hold what the totals claim (-7 past the packed values).
    s.discrete.resize(std::max<size_t>(s.discrete.size(), s.discreteTotal), -7);
    s.continuous.resize(std::max<size_t>(s.continuous.size(), s.continuousTotal), -7.0f);
    return s;
}

// One batch call on a world's members.
struct Outcome {
    verve_result result = VERVE_OK;
    std::vector<uint32_t> actions;
    std::vector<verve_result> verdicts;
};

Outcome batchCall(verve_batch* batch, const Step& s, const World& w) {
    std::vector<verve_agent*> crowd;
    for (size_t m : s.entries) crowd.push_back(m == kMaxMembers ? nullptr : w.members[m]);
    const uint32_t n = static_cast<uint32_t>(crowd.size());
    Outcome o;
    o.actions.assign(n, UINT32_MAX);
    o.verdicts.assign(n, VERVE_ERROR_INTERNAL);
    const uint32_t* dOffsets = s.discreteOffsets.empty() ? nullptr : s.discreteOffsets.data();
    const uint32_t* cOffsets = s.continuousOffsets.empty() ? nullptr : s.continuousOffsets.data();
    const uint32_t* shownOffsets = s.shownOffsets.empty() ? nullptr : s.shownOffsets.data();
    o.result = s.showsContinuous
                   ? verve_batch_update_demonstrated_continuous(
                         batch, crowd.data(), n, s.rewards.data(), s.discrete.data(), dOffsets, s.discreteTotal,
                         s.continuous.data(), cOffsets, s.continuousTotal, s.dt, s.demonstrated.data(),
                         s.shownContinuous.data(), shownOffsets, s.shownTotal, o.actions.data(), o.verdicts.data())
               : s.demonstrates
                   ? verve_batch_update_demonstrated(batch, crowd.data(), n, s.rewards.data(), s.discrete.data(), dOffsets,
                                                     s.discreteTotal, s.continuous.data(), cOffsets, s.continuousTotal, s.dt,
                                                     s.demonstrated.data(), o.actions.data(), o.verdicts.data())
                   : verve_batch_update(batch, crowd.data(), n, s.rewards.data(), s.discrete.data(), dOffsets,
                                        s.discreteTotal, s.continuous.data(), cOffsets, s.continuousTotal, s.dt,
                                        o.actions.data(), o.verdicts.data());
    VERVE_FUZZ_CHECK((o.result == VERVE_OK) == (verve_last_error()[0] == '\0'));
    return o;
}

// The batch on world a; the same step on its twin b by a batch of one worker.
void batchStep(const Step& s, World& a, World& b) {
    const std::vector<uint64_t> before = a.steps();
    const Outcome x = batchCall(batch(s.host), s, a);
    const Outcome y = batchCall(twinBatch(), s, b);
    VERVE_FUZZ_CHECK(x.result == y.result && x.verdicts == y.verdicts);
    const size_t n = s.entries.size();
    if (x.result != VERVE_OK) {
        VERVE_FUZZ_CHECK(a.steps() == before);
        // Every verdict written (none left from before the call), and no agent reads as fine
        // without some verdict saying why the call refused it (issue 32).
        bool named = false;
        for (size_t i = 0; i < n; ++i) {
            VERVE_FUZZ_CHECK(x.verdicts[i] != VERVE_ERROR_INTERNAL);
            named = named || x.verdicts[i] != VERVE_OK;
        }
        VERVE_FUZZ_CHECK(n == 0 || named);
        return;
    }
    for (size_t i = 0; i < n; ++i) {
        VERVE_FUZZ_CHECK(x.verdicts[i] == VERVE_OK);
        if (s.demonstrates && s.demonstrated[i] != VERVE_AGENT_CHOOSES) VERVE_FUZZ_CHECK(x.actions[i] == s.demonstrated[i]);
    }
    VERVE_FUZZ_CHECK(x.actions == y.actions);
}

// A member in both worlds: a body of brain k, or (past the brains) an agent of descriptor k.
void addMember(World& a, World& b, const std::vector<verve_agent_desc>& own, size_t k) {
    if (a.members.size() >= kMaxMembers) return;
    auto make = [&](World& w, verve_agent** out) {
        return k < w.brains.size() ? verve_brain_create_body(w.brains[k], out) : verve_agent_create(&own[k - w.brains.size()], out);
    };
    verve_agent *x = nullptr, *y = nullptr;
    if (make(a, &x) != VERVE_OK) {
        VERVE_FUZZ_CHECK(x == nullptr && verve_last_error()[0] != '\0');
        return;
    }
    VERVE_FUZZ_CHECK(make(b, &y) == VERVE_OK);
    a.members.push_back(x);
    b.members.push_back(y);
}

// Destroys handle i of a world's list and its twin, and takes them off both lists.
template <typename Handle>
void destroyIn(std::vector<Handle*>& a, std::vector<Handle*>& b, size_t i, void(VERVE_CALL* destroy)(Handle*)) {
    destroy(a[i]);
    destroy(b[i]);
    a.erase(a.begin() + static_cast<std::ptrdiff_t>(i));
    b.erase(b.begin() + static_cast<std::ptrdiff_t>(i));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider in(data, size);
    World a, b;
    // Up to two brains and two descriptors for agents of their own (refused descriptors make none).
    std::vector<verve_agent_desc> own;
    for (int i = 0, brains = in.ConsumeIntegralInRange<int>(0, 2); i < brains; ++i) {
        const verve_agent_desc d = crowdDescriptor(in);
        verve_brain *x = nullptr, *y = nullptr;
        if (verve_brain_create(&d, &x) != VERVE_OK) {
            VERVE_FUZZ_CHECK(x == nullptr && verve_last_error()[0] != '\0');
            continue;
        }
        VERVE_FUZZ_CHECK(verve_brain_create(&d, &y) == VERVE_OK);
        a.brains.push_back(x);
        b.brains.push_back(y);
    }
    for (int i = 0, kinds = in.ConsumeIntegralInRange<int>(a.brains.empty() ? 1 : 0, 2); i < kinds; ++i) {
        own.push_back(crowdDescriptor(in));
    }
    // A body of each brain and an agent of each descriptor to start with (more come from case 0).
    for (size_t k = 0; k < a.brains.size() + own.size(); ++k) addMember(a, b, own, k);
    size_t saveBytes = 0;
    for (int call = 0; call < 32 && in.remaining_bytes() > 0; ++call) {
        switch (in.ConsumeIntegralInRange<int>(0, 11)) {
            case 0:
                addMember(a, b, own, in.ConsumeIntegralInRange<size_t>(0, a.brains.size() + own.size() - 1));
                break;
            case 1:
            case 2:
            case 3:
            case 4:
            case 5:
            case 6:
                batchStep(readStep(in, a), a, b);
                break;
            case 7: {  // the end of a trial for one member, terminal or cut off, in both worlds
                if (a.members.empty()) break;
                const size_t m = in.ConsumeIntegralInRange<size_t>(0, a.members.size() - 1);
                const float reward = anyFloat(in, -1.5f, 1.5f);
                auto end = in.ConsumeBool() ? verve_agent_end_episode : verve_agent_truncate_episode;
                VERVE_FUZZ_CHECK(end(a.members[m], reward) == end(b.members[m], reward));
                break;
            }
            case 8: {  // a member leaves (a body's brain lives on in its other bodies and its handle)
                if (a.members.empty()) break;
                destroyIn(a.members, b.members, in.ConsumeIntegralInRange<size_t>(0, a.members.size() - 1), verve_agent_destroy);
                break;
            }
            case 9: {  // a brain's handle goes (its bodies keep what they share); no more bodies of it
                if (a.brains.empty()) break;
                destroyIn(a.brains, b.brains, in.ConsumeIntegralInRange<size_t>(0, a.brains.size() - 1), verve_brain_destroy);
                if (a.brains.empty() && own.empty()) own.push_back(crowdDescriptor(in));
                break;
            }
            case 10:
                if (a.brains.empty() || saveBytes >= verve_fuzz::kSaveBytesPerInput) break;
                verve_fuzz::brainRoundTrip(a.brains[in.ConsumeIntegralInRange<size_t>(0, a.brains.size() - 1)],
                                           in.ConsumeBool(), &saveBytes);
                break;
            case 11: {  // learning on or off for one member
                if (a.members.empty()) break;
                const size_t m = in.ConsumeIntegralInRange<size_t>(0, a.members.size() - 1);
                const int on = in.ConsumeIntegralInRange<int>(0, 1);
                VERVE_FUZZ_CHECK(verve_agent_set_learning(a.members[m], on) == VERVE_OK);
                VERVE_FUZZ_CHECK(verve_agent_set_learning(b.members[m], on) == VERVE_OK);
                break;
            }
        }
    }
    // The two batches' worlds end the same, member by member.
    for (size_t m = 0; m < a.members.size() && saveBytes < verve_fuzz::kSaveBytesPerInput; ++m) {
        const std::vector<char> x = verve_fuzz::savedBytes(static_cast<const verve_agent*>(a.members[m]), verve_agent_save_memory);
        saveBytes += 4 * x.size();
        VERVE_FUZZ_CHECK(x == verve_fuzz::savedBytes(static_cast<const verve_agent*>(b.members[m]), verve_agent_save_memory));
    }
    return 0;
}
