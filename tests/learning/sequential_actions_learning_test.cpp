// Sequential actions (thesis fig. 17): "100% correct after about 30 trials" of every 100-trial
// block; the original library reached 97.5%. We require >= 95% from trial 30 of each block on.
#include <gtest/gtest.h>

#include "learning_window.hpp"

using namespace verve::tasks;
using namespace verve::tasks::testing;

TEST(SequentialActionsLearning, EveryBlockIsLearnedByTrial30) {
    const LearningCurve c = learn("sequential-actions", 200, 700);
    for (std::size_t block = 0; block < 7; ++block) {
        const std::size_t start = block * 100;
        const Window early = windowOf(c, start + 30, start + 40);
        const Window rest = windowOf(c, start + 30, start + 100);
        print("block " + std::to_string(block) + " trials 30-39", early);
        EXPECT_GE(early.success, 0.95) << "block " << block;
        EXPECT_GE(rest.success, 0.95) << "block " << block;
    }
    EXPECT_GE(windowOf(c, 630, 700).success, 0.975);  // the original's final 97.5%
}
