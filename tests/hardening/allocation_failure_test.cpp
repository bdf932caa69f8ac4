// Allocation failure: a fixed scenario (create, 120 updates (6 for the 32-sensor agent), a quarter of them demonstrated, a teacher's judgements, with RBF growth, planning and an
// episode end, an XML save and load, then a binary save and load) runs once for every N, with the N-th allocation failing. The
// call that meets the failure must return VERVE_ERROR_OUT_OF_MEMORY and leave the agent exactly
// as it was (its save byte-identical), and the scenario, retried from there, must end in the same
// agent as a run without failures. Run under ASan by scripts/sanitize.sh.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "hardening_support.hpp"
#include "memory_hooks.hpp"

namespace verve::hardening {
namespace {

// The save of an agent, made with allocation failures off and not counted.
std::string bytesOf(const verve_agent* agent, CountingAllocator& allocator) {
    return uncounted(allocator, [&] { return saveToString(agent); });
}

class Scenario {
public:
    // `updates`: 120, or fewer for an agent whose every step allocates much (32 sensors: 63 lattices).
    Scenario(CountingAllocator& allocator, const verve_agent_desc& desc, int updates)
        : allocator_(allocator), desc_(desc), updates_(updates) {}
    ~Scenario() { verve_agent_destroy(agent_); }

    int calls() const { return updates_ + 7; }

    // Call i of the scenario on the current agent.
    verve_result call(int i) {
        if (i == 0) return verve_agent_create(&desc_, &agent_);
        if (i <= updates_) {
            if (i == updates_ / 2) return verve_agent_end_episode(agent_, 1.0f);
            if (i == 2) return verve_agent_teach(agent_, 0.0f);  // the teacher's memory, from here on
            if (i % 10 == 5) return verve_agent_teach(agent_, i % 20 == 5 ? 1.0f : -0.5f);
            // Sensor 0 of each kind as the 1-discrete, 2-continuous scenarios always read; more sensors
            // (the 32-sensor agent) wander too.
            const uint32_t nd = desc_.num_discrete_sensors, nc = desc_.num_continuous_sensors;
            std::vector<int32_t> disc(nd);
            std::vector<float> c(nc);
            for (uint32_t k = 0; k < nd; ++k) {
                const uint32_t values = k < 16 ? desc_.discrete_sensor_values[k] : desc_.more_discrete_sensor_values[k - 16];
                disc[k] = static_cast<int32_t>((static_cast<uint32_t>(i) + k) % values);
            }
            for (uint32_t k = 0; k < nc; ++k) {
                const float t = static_cast<float>(i);
                c[k] = k == 0 ? std::sin(0.9f * t) : k == 1 ? std::cos(0.4f * t) : std::sin(0.3f * t * static_cast<float>(k) + static_cast<float>(k));
            }
            uint32_t action = 0;
            if (i % 8 == 1 && desc_.num_continuous_actions > 0) {  // with the teacher's continuous actions
                const float steer[2] = {c[0], i % 16 == 1 ? 1.0f : -0.5f};
                return verve_agent_update_demonstrated_continuous(agent_, -0.1f, disc.data(), nd, c.data(), nc, 0.1f, nullptr, 0,
                                                                  static_cast<uint32_t>(i % 2), steer, 2);
            }
            if (i % 4 == 1) {  // a demonstrated step (docs/teaching.md)
                return verve_agent_update_demonstrated(agent_, i % 9 == 0 ? 1.0f : -0.1f, disc.data(), nd, c.data(), nc, 0.1f,
                                                       nullptr, 0, static_cast<uint32_t>(i % 2));
            }
            return verve_agent_update(agent_, i % 9 == 0 ? 1.0f : -0.1f, disc.data(), nd, c.data(), nc, 0.1f, &action);
        }
        const int after = i - updates_;
        if (after == 1 || after == 4) {  // the size query, then the save itself (XML, then binary)
            size_ = 0;
            return (after == 1 ? verve_agent_save_memory : verve_agent_save_memory_binary)(agent_, nullptr, &size_);
        }
        if (after == 2 || after == 5) {
            saved_.assign(size_, '\0');
            return (after == 2 ? verve_agent_save_memory : verve_agent_save_memory_binary)(agent_, &saved_[0], &size_);
        }
        verve_agent* loaded = nullptr;
        const verve_result r = verve_agent_load_memory(saved_.data(), size_, &loaded);
        if (r == VERVE_OK) {
            verve_agent_destroy(agent_);
            agent_ = loaded;
        } else if (loaded != nullptr) {
            return VERVE_ERROR_INTERNAL;  // a failed load must hand out nothing
        }
        return r;
    }

    const verve_agent* agent() const { return agent_; }

private:
    CountingAllocator& allocator_;
    verve_agent_desc desc_;
    int updates_;
    verve_agent* agent_ = nullptr;
    size_t size_ = 0;
    std::string saved_;
};

void sweep(const verve_agent_desc& desc, int updates = 120) {
    CountingAllocator allocator;
    const verve_hooks hooks = allocator.hooks();
    ASSERT_EQ(verve_set_hooks(&hooks), VERVE_OK) << lastError();

    // The reference run: every call succeeds. Allocations up to the end of each call, and the
    // agent's save at the end.
    std::string reference;
    std::vector<long> upTo;
    {
        Scenario s(allocator, desc, updates);
        for (int i = 0; i < s.calls(); ++i) {
            ASSERT_EQ(s.call(i), VERVE_OK) << "call " << i << ": " << lastError();
            upTo.push_back(allocator.allocations.load());
        }
        reference = bytesOf(s.agent(), allocator);
    }
    const long total = upTo.back();
    ASSERT_GT(total, 500);
    ::testing::Test::RecordProperty("allocations", static_cast<int>(total));

    int failures = 0;
    for (long n = 1; n <= total; ++n) {
        allocator.allocations = 0;
        allocator.failAt = n;
        Scenario s(allocator, desc, updates);
        bool failed = false;
        for (int i = 0; i < s.calls(); ++i) {
            // Deterministic: allocation n falls in the same call as in the reference run.
            const bool hit = !failed && n <= upTo[static_cast<std::size_t>(i)];
            const std::string before = hit && s.agent() != nullptr ? bytesOf(s.agent(), allocator) : std::string();
            const verve_result r = s.call(i);
            if (!hit) {
                ASSERT_EQ(r, VERVE_OK) << "N=" << n << " call " << i << ": " << lastError();
                continue;
            }
            ASSERT_EQ(r, VERVE_ERROR_OUT_OF_MEMORY) << "N=" << n << " call " << i << ": " << lastError();
            ASSERT_NE(lastError().find("out of memory"), std::string::npos) << lastError();
            if (s.agent() != nullptr) {
                ASSERT_EQ(bytesOf(s.agent(), allocator), before) << "N=" << n << " call " << i << " changed the agent";
            }
            failed = true;
            ++failures;
            allocator.failAt = -1;
            ASSERT_EQ(s.call(i), VERVE_OK) << "N=" << n << " retrying call " << i << ": " << lastError();
        }
        ASSERT_TRUE(failed) << "allocation " << n << " never happened";
        ASSERT_EQ(bytesOf(s.agent(), allocator), reference) << "N=" << n << ": the retried scenario ends elsewhere";
    }
    EXPECT_EQ(failures, total);
    ASSERT_EQ(verve_set_hooks(nullptr), VERVE_OK) << lastError();
}

TEST(AllocationFailure, EveryFailedAllocationLeavesTheAgentAsItWas) { sweep(mixedDesc(true, 11)); }

// Sensor groups: a step adds an RBF in every group that lacks one, all or none.
TEST(AllocationFailure, EveryFailedAllocationLeavesAnAgentWithSensorGroupsAsItWas) {
    verve_agent_desc d = mixedDesc(false, 11);
    d.sensor_grouping = VERVE_GROUPING_CUSTOM;
    d.num_sensor_groups = 3;
    d.sensor_groups[0] = 0b01;
    d.sensor_groups[1] = 0b10;
    d.sensor_groups[2] = 0b11;
    sweep(d);
}

// Action branches: a step marks and imitates one neuron per branch, praise credits each.
TEST(AllocationFailure, EveryFailedAllocationLeavesAnAgentWithActionBranchesAsItWas) {
    verve_agent_desc d = mixedDesc(false, 11);
    d.num_actions = 0;
    d.num_action_branches = 3;
    d.action_branches[0] = 3;
    d.action_branches[1] = 2;
    d.action_branches[2] = 2;
    sweep(d);
}

// Continuous actions: their columns' traces and clamps, their values and noise, demonstrated values
// and the teacher's memory of their gradients.
TEST(AllocationFailure, EveryFailedAllocationLeavesAnAgentWithContinuousActionsAsItWas) {
    verve_agent_desc d = mixedDesc(false, 13);
    d.num_continuous_actions = 2;
    sweep(d);
}

// 32 continuous sensors (Auto: 63 lattices, each adding its RBF all or none) and 17 discrete ones,
// described in the V8 struct's arrays beyond sensor 16.
TEST(AllocationFailure, EveryFailedAllocationLeavesA32SensorAgentAsItWas) {
    verve_agent_desc d = mixedDesc(false, 17);
    d.num_continuous_sensors = 32;
    d.more_continuous_sensor_circular[4] = 1;
    d.num_discrete_sensors = 17;
    for (uint32_t k = 1; k < 16; ++k) d.discrete_sensor_values[k] = 1;
    d.more_discrete_sensor_values[0] = 2;
    sweep(d, 6);  // every step allocates in 63 lattices: 120 would take many minutes
}

}  // namespace
}  // namespace verve::hardening
