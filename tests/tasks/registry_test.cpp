#include <gtest/gtest.h>

#include <set>

#include "tasks/registry.hpp"
#include "tasks/task.hpp"

using namespace verve::tasks;

TEST(Registry, EveryTaskBuildsReportsItsNameAndHasAValidDescriptor) {
    std::set<std::string> names;
    for (const TaskInfo& info : taskRegistry()) {
        EXPECT_TRUE(names.insert(info.name).second) << "duplicate " << info.name;
        auto env = info.make(1);
        ASSERT_NE(env, nullptr);
        EXPECT_EQ(env->name(), info.name);
        EXPECT_NO_THROW(env->agentDescriptor().validate()) << info.name;
        EXPECT_GT(info.runs, 0u);
        EXPECT_GT(info.trials, 0u);
        EXPECT_FALSE(info.description.empty());
    }
    EXPECT_EQ(names.size(), 31u);
}

TEST(Registry, FindsByNameAndPlanningVariantsArePlanning) {
    EXPECT_EQ(findTask("no-such-task"), nullptr);
    const TaskInfo* maze = findTask("maze2-planning");
    ASSERT_NE(maze, nullptr);
    const auto d = maze->make(1)->agentDescriptor();
    EXPECT_TRUE(d.planning);
    EXPECT_EQ(d.maxPlanningSteps, 50u);
    EXPECT_FALSE(findTask("maze2")->make(1)->agentDescriptor().planning);
}
