// A teacher's praise (docs/teaching.md): a pet sees one of four cues and must answer each with its
// own action; then it idles for a second (and keeps acting) while the teacher, who judges only the
// answer, clicks "good" or "bad" 0.2-2 s after it, by then maybe after the next answer too. There is no game reward at all. Thresholds come from measurements
// over these seeds.
#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <utility>
#include <random>

#include "verve/agent.hpp"

namespace {

constexpr int kCues = 4;
constexpr float kDt = 0.1f;
constexpr int kIdleSteps = 10;  // 1 s of idling after each answer
constexpr int kTrials = 200;

enum class Teacher { Right, Random };

// P(the right answer), averaged over the cues, from the policy after kTrials judged answers. The
// judgements of one answer may arrive after the next answers (a trial lasts 1.1 s).
double rightAfterTraining(std::uint64_t seed, float delaySeconds, Teacher teacher) {
    verve::AgentDescriptor d;
    d.discreteSensors = {kCues + 1};  // 0: no cue
    d.numActions = kCues;
    d.seed = seed;
    verve::Agent pet(d);
    pet.teach(0.0f);  // the teacher arrives: the pet starts remembering its acts
    std::mt19937 rng(static_cast<std::uint32_t>(seed) * 7919u);
    const int delaySteps = static_cast<int>(delaySeconds / kDt + 0.5f);
    std::deque<std::pair<int, float>> due;  // (step, judgement)
    int step = 0;
    for (int trial = 0; trial < kTrials; ++trial) {
        for (int k = 0; k <= kIdleSteps; ++k, ++step) {
            const std::int32_t cue = k == 0 ? 1 + static_cast<std::int32_t>(rng() % kCues) : 0;
            const std::uint32_t a = pet.update(0.0f, verve::ObservationView{&cue, 1, nullptr, 0}, kDt);
            if (k == 0) {
                const bool right = a == static_cast<std::uint32_t>(cue - 1);
                const float judgement = teacher == Teacher::Right ? (right ? 1.0f : -1.0f) : (rng() % 2 ? 1.0f : -1.0f);
                due.emplace_back(step + delaySteps, judgement);
            }
            while (!due.empty() && due.front().first == step) {
                pet.teach(due.front().second);  // delaySeconds after the answer
                due.pop_front();
            }
        }
    }
    pet.setLearning(false);
    double right = 0.0;
    for (std::int32_t cue = 1; cue <= kCues; ++cue) {
        pet.update(0.0f, verve::ObservationView{&cue, 1, nullptr, 0}, kDt);
        right += pet.actionProbabilities()[static_cast<std::size_t>(cue - 1)] / kCues;
    }
    return right;
}

double meanRight(float delaySeconds, Teacher teacher) {
    double sum = 0.0;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) sum += rightAfterTraining(seed, delaySeconds, teacher) / 10.0;
    return sum;
}

}  // namespace

// Measured (seeds 1-10): P(right) 0.759 / 0.900 / 0.900 / 0.957 judged 0.2 / 0.5 / 1 / 2 s after the
// answer (at 0.2 s the window still holds the two answers before); a random teacher 0.247.
TEST(TeacherLearning, PraiseReachesTheAnswerItJudgesAfterAnyHumanDelay) {
    for (float delay : {0.2f, 0.5f, 1.0f, 2.0f}) {
        const double right = meanRight(delay, Teacher::Right);
        std::printf("judged %.1f s after the answer: P(right) %.3f (chance 0.25)\n", delay, right);
        RecordProperty("delay_" + std::to_string(delay), std::to_string(right));
        EXPECT_GT(right, 0.6) << delay;
    }
    const double random = meanRight(0.5f, Teacher::Random);
    std::printf("a teacher who clicks at random: P(right) %.3f\n", random);
    EXPECT_LT(random, 0.4);
}
