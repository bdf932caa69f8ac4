// Action branches: the combined index, the descriptor's checks, and an agent that chooses, masks,
// learns and imitates one choice per branch.
#include "core/action_branches.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "discrete_obs.hpp"
#include "verve/agent.hpp"
#include "validation_error.hpp"
#include "verve/error.hpp"

using namespace verve;
using verve::coretest::validationError;
using verve::coretest::discreteObs;

namespace {

AgentDescriptor branched(std::vector<std::uint32_t> sizes) {
    AgentDescriptor d;
    d.addDiscreteSensor(2);
    d.setActionBranches(std::move(sizes));
    return d;
}

float branchSum(const std::vector<float>& p, std::size_t from, std::size_t n) {
    return std::accumulate(p.begin() + from, p.begin() + from + n, 0.0f);
}

}  // namespace

TEST(ActionBranches, CombinedActionsSplitAndJoinBranchZeroFastest) {
    const AgentDescriptor d = branched({3, 2, 4});
    EXPECT_EQ(d.numActions, 24u);
    EXPECT_EQ(d.actionChoices(), 9u);
    for (std::uint32_t a = 0; a < 24; ++a) {
        const std::uint32_t choices[3] = {d.branchChoice(a, 0), d.branchChoice(a, 1), d.branchChoice(a, 2)};
        EXPECT_EQ(a, choices[0] + 3 * (choices[1] + 2 * choices[2]));
        EXPECT_EQ(d.actionOf(choices, 3), a);
        const core::ActionBranches b = core::ActionBranches::of(d);
        std::uint32_t columns[core::ActionBranches::kMax];
        ASSERT_EQ(b.columnsOf(a, columns), 3u);
        EXPECT_EQ(columns[0], choices[0]);
        EXPECT_EQ(columns[1], 3 + choices[1]);
        EXPECT_EQ(columns[2], 5 + choices[2]);
    }
    const std::uint32_t bad[3] = {0, 2, 0};
    EXPECT_THROW(d.actionOf(bad, 3), Error);  // branch 1 has 2 choices
    EXPECT_THROW(d.actionOf(bad, 2), Error);  // one choice per branch
    AgentDescriptor one;
    one.numActions = 5;
    EXPECT_EQ(one.actionChoices(), 5u);
    EXPECT_EQ(one.branchChoice(4, 0), 4u);
    const std::uint32_t four = 4;
    EXPECT_EQ(one.actionOf(&four, 1), 4u);
}

TEST(ActionBranches, TheDescriptorNamesWhatIsWrong) {
    EXPECT_EQ(validationError(branched({3, 3, 2})), "");
    AgentDescriptor d = branched({3, 3});
    d.numActions = 6;
    EXPECT_NE(validationError(d).find("num_actions must be the product of action_branches (9), got 6"), std::string::npos);
    EXPECT_NE(validationError(branched({3, 0})).find("action_branches[1] must be at least 1"), std::string::npos);
    EXPECT_NE(validationError(branched(std::vector<std::uint32_t>(9, 2))).find("the number of action_branches is 9, at most 8"),
              std::string::npos);
    EXPECT_NE(validationError(branched({64, 64, 2})).find("above 4096"), std::string::npos);
    d = branched({2, 2});
    d.planning = true;
    EXPECT_NE(validationError(d).find("planning needs one action set"), std::string::npos);
    EXPECT_THROW(Agent{d}, Error);
}

TEST(ActionBranches, OneBranchIsExactlyOneActionSet) {
    AgentDescriptor set;
    set.addDiscreteSensor(2);
    set.numActions = 4;
    Agent a(set), b(branched({4}));
    for (int t = 0; t < 300; ++t) {
        const float reward = t % 7 == 0 ? 1.0f : -0.1f;
        ASSERT_EQ(a.update(reward, discreteObs(t % 2), 0.1f), b.update(reward, discreteObs(t % 2), 0.1f));
    }
    EXPECT_EQ(a.snapshot().weights, b.snapshot().weights);
}

TEST(ActionBranches, ProbabilitiesAndMasksHoldEachBranchInTurn) {
    Agent agent(branched({3, 2}));
    std::vector<float> p = agent.actionProbabilities();
    ASSERT_EQ(p.size(), 5u);
    EXPECT_FLOAT_EQ(p[0], 1.0f / 3.0f);
    EXPECT_FLOAT_EQ(p[4], 0.5f);
    // Branch 0 may only choose 2; branch 1 either.
    const std::uint8_t allowed[5] = {0, 0, 1, 1, 1};
    for (int t = 0; t < 50; ++t) {
        const std::uint32_t a = agent.update(0.0f, discreteObs(t % 2).view(), 0.1f, ActionMask{allowed, 5});
        EXPECT_EQ(agent.descriptor().branchChoice(a, 0), 2u);
        p = agent.actionProbabilities();
        EXPECT_FLOAT_EQ(p[2], 1.0f);
        EXPECT_NEAR(branchSum(p, 3, 2), 1.0f, 1e-6f);
    }
    const std::uint8_t noTurn[5] = {1, 1, 1, 0, 0};
    const std::uint8_t product[6] = {1, 1, 1, 1, 1, 1};
    const auto before = agent.snapshot().weights;
    EXPECT_THROW(agent.update(0.0f, discreteObs(0).view(), 0.1f, ActionMask{noTurn, 5}), Error);
    EXPECT_THROW(agent.update(0.0f, discreteObs(0).view(), 0.1f, ActionMask{product, 6}), Error);
    EXPECT_THROW(agent.updateDemonstrated(0.0f, discreteObs(0).view(), 0.1f, 0, ActionMask{allowed, 5}), Error);  // choice 0 masked
    EXPECT_THROW(agent.updateDemonstrated(0.0f, discreteObs(0).view(), 0.1f, 6, ActionMask{}), Error);  // 6 combined actions
    EXPECT_EQ(agent.snapshot().weights, before);
}

TEST(ActionBranches, OneTdErrorCreditsEachBranchsOwnChoice) {
    // A bandit: the reward is 1 when branch 0 chooses 1, whatever branch 1 does, and branch 1's
    // choice 0 costs 0.5. Each head must learn its own part from the one shared reward.
    AgentDescriptor d = branched({3, 2});
    d.tauDiscount = 0.0f;
    Agent agent(d);
    for (int t = 0; t < 3000; ++t) {
        const std::uint32_t a = agent.update(0.0f, discreteObs(0), 0.1f);
        const float reward = (d.branchChoice(a, 0) == 1 ? 1.0f : 0.0f) - (d.branchChoice(a, 1) == 0 ? 0.5f : 0.0f);
        agent.endEpisode(reward);
    }
    agent.setActionSelection(ActionSelection::Greedy);
    const std::uint32_t a = agent.update(0.0f, discreteObs(0), 0.1f);
    EXPECT_EQ(d.branchChoice(a, 0), 1u);
    EXPECT_EQ(d.branchChoice(a, 1), 1u);
    const std::vector<float>& p = agent.actionProbabilities();
    EXPECT_GT(p[1], 0.8f);
    EXPECT_GT(p[4], 0.8f);
}

TEST(ActionBranches, DemonstrationsAndPraisePullEveryBranchTowardsTheAct) {
    const AgentDescriptor d = branched({3, 3});
    const std::uint32_t shown[2] = {2, 0};
    Agent pupil(d);
    for (int t = 0; t < 200; ++t) pupil.updateDemonstrated(0.0f, discreteObs(0).view(), 0.1f, d.actionOf(shown, 2));
    pupil.setActionSelection(ActionSelection::Greedy);
    EXPECT_EQ(pupil.update(0.0f, discreteObs(0), 0.1f), d.actionOf(shown, 2));

    Agent pet(d);
    pet.teach(0.0f);
    for (int t = 0; t < 400; ++t) {  // 3 s per act: a judgement (2.5 s back) reaches this act alone
        const std::uint32_t a = pet.update(0.0f, discreteObs(0), 3.0f);
        pet.teach(d.branchChoice(a, 0) == 2 && d.branchChoice(a, 1) == 0 ? 1.0f : -0.2f);
    }
    pet.setActionSelection(ActionSelection::Greedy);
    EXPECT_EQ(pet.update(0.0f, discreteObs(0), 0.1f), d.actionOf(shown, 2));
}
