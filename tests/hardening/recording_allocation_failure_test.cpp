// Allocation failure in recordings (docs/teaching.md, "Recordings"): a fixed scenario (make a
// recording shaped like an agent, record steps (half with continuous actions) and trial ends, save it to memory and load it back,
// replay it into a fresh agent) runs once for every N, with the N-th allocation failing. The call
// that meets the failure returns VERVE_ERROR_OUT_OF_MEMORY; a refused add leaves the recording as it
// was; a replay stopped part-way keeps what it replayed (documented), so the scenario retries it
// into a fresh agent. Retried, the scenario must end in the same recording and the same agent.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "hardening_support.hpp"
#include "memory_hooks.hpp"

namespace verve::hardening {
namespace {

std::string recordingBytes(const verve_recording* r) {
    size_t size = 0;
    if (verve_recording_save_memory(r, nullptr, &size) != VERVE_OK) return "(no save)";
    std::string bytes(size, '\0');
    if (verve_recording_save_memory(r, &bytes[0], &size) != VERVE_OK) return "(no save)";
    return bytes;
}

verve_agent_desc withContinuousActions(verve_agent_desc d) {
    d.num_continuous_actions = 2;  // half the steps carry the teacher's values
    return d;
}

class Scenario {
public:
    explicit Scenario(CountingAllocator& allocator) : allocator_(allocator) {}
    ~Scenario() {
        verve_recording_destroy(recording_);
        verve_agent_destroy(shape_);
        verve_agent_destroy(learner_);
    }
    static int calls() { return 48; }
    bool replays(int i) const { return i == 47; }

    verve_result call(int i) {
        if (i == 0) return verve_agent_create(&desc_, &shape_);
        if (i == 1) return verve_recording_create(shape_, &recording_);
        if (i < 42) {
            if (i % 10 == 0) return verve_recording_add_end_episode(recording_, 1.0f);
            if (i == 25) return verve_recording_add_truncation(recording_, -0.5f);
            const int32_t disc = i % 3;
            const float c[2] = {std::sin(0.9f * static_cast<float>(i)), std::cos(0.4f * static_cast<float>(i))};
            if (i % 2 == 0) {  // with the teacher's continuous actions
                const float steer[2] = {c[1], i % 4 == 0 ? 1.0f : -1.0f};
                return verve_recording_add_step_continuous(recording_, -0.1f, &disc, 1, c, 2, 0.1f, static_cast<uint32_t>(i % 3),
                                                           steer, 2);
            }
            return verve_recording_add_step(recording_, i % 9 == 0 ? 1.0f : -0.1f, &disc, 1, c, 2, 0.1f,
                                            static_cast<uint32_t>(i % 3));
        }
        if (i == 42) {
            size_ = 0;
            return verve_recording_save_memory(recording_, nullptr, &size_);
        }
        if (i == 43) {
            saved_.assign(size_, '\0');
            return verve_recording_save_memory(recording_, &saved_[0], &size_);
        }
        if (i == 44) {
            verve_recording* loaded = nullptr;
            const verve_result r = verve_recording_load_memory(saved_.data(), size_, &loaded);
            if (r == VERVE_OK) {
                verve_recording_destroy(recording_);
                recording_ = loaded;
            } else if (loaded != nullptr) {
                return VERVE_ERROR_INTERNAL;  // a failed load must hand out nothing
            }
            return r;
        }
        if (i == 45) return verve_agent_create(&desc_, &learner_);
        if (i == 46) return verve_agent_set_learning(learner_, 1);
        return verve_agent_replay(learner_, recording_);
    }
    // A replay stopped part-way: the scenario starts it again into a fresh agent.
    void freshLearner() {
        verve_agent_destroy(learner_);
        learner_ = nullptr;
        ASSERT_EQ(verve_agent_create(&desc_, &learner_), VERVE_OK);
    }

    std::string recording() const {
        return recording_ == nullptr ? std::string() : uncounted(allocator_, [&] { return recordingBytes(recording_); });
    }
    std::string learner() const {
        return learner_ == nullptr ? std::string() : uncounted(allocator_, [&] { return saveToString(learner_); });
    }

private:
    CountingAllocator& allocator_;
    verve_agent_desc desc_ = withContinuousActions(mixedDesc(false, 5));
    verve_agent* shape_ = nullptr;
    verve_agent* learner_ = nullptr;
    verve_recording* recording_ = nullptr;
    size_t size_ = 0;
    std::string saved_;
};

TEST(AllocationFailure, EveryFailedAllocationInARecordingIsReportedAndRetried) {
    CountingAllocator allocator;
    const verve_hooks hooks = allocator.hooks();
    ASSERT_EQ(verve_set_hooks(&hooks), VERVE_OK) << lastError();

    std::string referenceRecording, referenceLearner;
    std::vector<long> upTo;
    {
        Scenario s(allocator);
        for (int i = 0; i < Scenario::calls(); ++i) {
            ASSERT_EQ(s.call(i), VERVE_OK) << "call " << i << ": " << lastError();
            upTo.push_back(allocator.allocations.load());
        }
        referenceRecording = s.recording();
        referenceLearner = s.learner();
    }
    const long total = upTo.back();
    ASSERT_GT(total, 20);
    RecordProperty("allocations", static_cast<int>(total));

    for (long n = 1; n <= total; ++n) {
        allocator.allocations = 0;
        allocator.failAt = n;
        Scenario s(allocator);
        bool failed = false;
        for (int i = 0; i < Scenario::calls(); ++i) {
            const bool hit = !failed && n <= upTo[static_cast<std::size_t>(i)];
            const std::string before = hit ? s.recording() : std::string();
            const verve_result r = s.call(i);
            if (!hit) {
                ASSERT_EQ(r, VERVE_OK) << "N=" << n << " call " << i << ": " << lastError();
                continue;
            }
            ASSERT_EQ(r, VERVE_ERROR_OUT_OF_MEMORY) << "N=" << n << " call " << i << ": " << lastError();
            ASSERT_EQ(s.recording(), before) << "N=" << n << " call " << i << " changed the recording";
            failed = true;
            allocator.failAt = -1;
            if (s.replays(i)) s.freshLearner();
            ASSERT_EQ(s.call(i), VERVE_OK) << "N=" << n << " retrying call " << i << ": " << lastError();
        }
        ASSERT_TRUE(failed) << "allocation " << n << " never happened";
        ASSERT_EQ(s.recording(), referenceRecording) << "N=" << n;
        ASSERT_EQ(s.learner(), referenceLearner) << "N=" << n << ": the retried scenario ends elsewhere";
    }
    ASSERT_EQ(verve_set_hooks(nullptr), VERVE_OK) << lastError();
}

}  // namespace
}  // namespace verve::hardening
