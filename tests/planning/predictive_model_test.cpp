// The predictive model on its own: exact one-shot learning with rate 1, categorical discrete
// outputs, uncertainty that starts full and falls, terminal transitions.
#include "core/predictive_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/state_representation.hpp"
#include "core/weight_table.hpp"

using namespace verve;
using namespace verve::core;

namespace {

AgentDescriptor gridAgent() {
    AgentDescriptor d;
    d.addDiscreteSensor(4).addDiscreteSensor(3);
    d.numActions = 2;
    d.planning = true;
    d.tauModel = 0.0f;
    return d;
}

// One continuous sensor at resolution 10, one action, planning on.
AgentDescriptor lineAgent() {
    AgentDescriptor d;
    d.addContinuousSensor();
    d.numActions = 1;
    d.planning = true;
    d.resolution = 10;
    d.adaptation &= ~verve::Adaptation::FineLattice;  // one lattice: the tests count and place its RBFs
    return d;
}

struct Fixture {
    explicit Fixture(const AgentDescriptor& d) : desc(d), rep(d), model(d), weights(layoutFor(d)) {}
    static WeightLayout layoutFor(const AgentDescriptor& d) {
        WeightLayout l;
        l.numActions = d.numActions;
        l.modelColumns = PredictiveModel::columnsFor(d);
        return l;
    }
    std::vector<ActiveFeature> features(std::vector<std::int32_t> discrete, std::vector<float> continuous = {}) {
        std::vector<ActiveFeature> phi;
        rep.activate(discrete.data(), continuous.data(), true, phi);
        weights.resize(rep.featureCount());
        return phi;
    }
    AgentDescriptor desc;
    StateRepresentation rep;
    PredictiveModel model;
    WeightTable weights;
};

}  // namespace

TEST(PredictiveModel, NeedsNoColumnsWithoutPlanning) {
    AgentDescriptor d = gridAgent();
    d.planning = false;
    EXPECT_EQ(PredictiveModel::columnsFor(d), 0u);
    d.planning = true;
    // Per action: 4 + 3 categorical outputs, reward, terminal, certainty, fast and slow error.
    EXPECT_EQ(PredictiveModel::columnsFor(d), 2u * (7u + 5u));
    d.discretePrediction = DiscretePrediction::Ordinal;
    EXPECT_EQ(PredictiveModel::columnsFor(d), 2u * (2u + 5u));
}

TEST(PredictiveModel, UnknownTransitionsAreFullyUncertain) {
    Fixture f(gridAgent());
    const auto phi = f.features({1, 2});
    Prediction p;
    f.model.predict(f.weights, phi, 0, nullptr, p);
    EXPECT_FLOAT_EQ(p.uncertainty, 1.0f);
    EXPECT_FLOAT_EQ(p.progress, 0.0f);
}

TEST(PredictiveModel, RateOneLearnsADeterministicTransitionAtOnce) {
    Fixture f(gridAgent());
    const auto phi = f.features({1, 2});
    const std::int32_t next[] = {3, 0};
    const float firstError = f.model.train(f.weights, phi, 1, nullptr, next, nullptr, -0.5f, 1.0f);
    EXPECT_GT(firstError, 0.1f);
    Prediction p;
    f.model.predict(f.weights, phi, 1, nullptr, p);
    EXPECT_EQ(p.discrete, (std::vector<std::int32_t>{3, 0}));
    EXPECT_FLOAT_EQ(p.reward, -0.5f);
    EXPECT_FLOAT_EQ(p.terminal, 0.0f);
    // The uncertainty estimate learned the error of the old prediction; a second identical
    // transition is predicted exactly, and then the estimate falls to zero.
    EXPECT_NEAR(p.uncertainty, firstError, 1e-6f);
    EXPECT_FLOAT_EQ(f.model.train(f.weights, phi, 1, nullptr, next, nullptr, -0.5f, 1.0f), 0.0f);
    f.model.predict(f.weights, phi, 1, nullptr, p);
    EXPECT_FLOAT_EQ(p.uncertainty, 0.0f);
    EXPECT_GT(p.progress, 0.0f);  // the error fell: learning progress
    // The other action learned nothing.
    f.model.predict(f.weights, phi, 0, nullptr, p);
    EXPECT_FLOAT_EQ(p.uncertainty, 1.0f);
}

TEST(PredictiveModel, TerminalTransitionsTeachTheEndAndTheReward) {
    Fixture f(gridAgent());
    const auto phi = f.features({0, 0});
    f.model.trainTerminal(f.weights, phi, 0, 1.0f, 1.0f);
    Prediction p;
    f.model.predict(f.weights, phi, 0, nullptr, p);
    EXPECT_FLOAT_EQ(p.terminal, 1.0f);
    EXPECT_FLOAT_EQ(p.reward, 1.0f);
}

TEST(PredictiveModel, NoiseKeepsUncertaintyButNotProgress) {
    Fixture f(gridAgent());
    const auto phi = f.features({2, 1});
    // A screen showing a random value: its error never falls.
    std::uint32_t state = 12345;
    Prediction p;
    float uncertaintySum = 0.0f, progressSum = 0.0f;
    for (int i = 0; i < 2000; ++i) {
        state = state * 1664525u + 1013904223u;
        const std::int32_t next[] = {static_cast<std::int32_t>((state >> 16) % 4), 0};
        f.model.train(f.weights, phi, 0, nullptr, next, nullptr, 0.0f, 1.0f);
        if (i >= 1000) {
            f.model.predict(f.weights, phi, 0, nullptr, p);
            uncertaintySum += p.uncertainty;
            progressSum += p.progress;
        }
    }
    EXPECT_GT(uncertaintySum / 1000.0f, 0.1f);
    EXPECT_LT(std::abs(progressSum / 1000.0f), 0.05f);
}

namespace {

// x -> x + 0.1 on four sample points, 300 epochs; `change`: the model learns the step, else the
// position. Returns the sample points' features.
constexpr float kSamplePoints[] = {-0.6f, -0.2f, 0.2f, 0.6f};
std::vector<std::vector<ActiveFeature>> trainOnAStepRight(Fixture& f, bool change) {
    std::vector<std::vector<ActiveFeature>> phis;
    for (float x : kSamplePoints) phis.push_back(f.features({}, {x}));
    for (int epoch = 0; epoch < 300; ++epoch) {
        for (std::size_t i = 0; i < 4; ++i) {
            const float next = kSamplePoints[i] + 0.1f;
            f.model.train(f.weights, phis[i], 0, change ? &kSamplePoints[i] : nullptr, nullptr, &next, 0.0f,
                          f.model.rate(0.1f));
        }
    }
    return phis;
}

}  // namespace

TEST(PredictiveModel, ContinuousPredictionsConvergeWithTheDeltaRule) {
    Fixture f(lineAgent());
    // The linear network over RBFs fits the positions at the sample points.
    const auto phis = trainOnAStepRight(f, false);
    Prediction p;
    for (std::size_t i = 0; i < 4; ++i) {
        f.model.predict(f.weights, phis[i], 0, nullptr, p);
        EXPECT_NEAR(p.continuous[0], kSamplePoints[i] + 0.1f, 0.02f);
        EXPECT_LT(p.uncertainty, 0.1f);
    }
}

// Why the model predicts changes: x -> x + 0.1 is the same step everywhere, which the RBFs fit
// exactly; as positions it is a ramp they only approximate. Trained on four points, both are asked
// about points in between, which they never saw.
TEST(PredictiveModel, ChangesGeneraliseWherePositionsBlur) {
    auto worstError = [](bool change) {
        Fixture f(lineAgent());
        trainOnAStepRight(f, change);
        float worst = 0.0f;
        Prediction p;
        for (float x : {-0.4f, 0.0f, 0.4f}) {
            std::vector<ActiveFeature> phi;
            f.rep.find(nullptr, &x, phi);  // no new RBF: only the four trained ones are found
            f.model.predict(f.weights, phi, 0, change ? &x : nullptr, p);
            worst = std::max(worst, std::fabs(p.continuous[0] - (x + 0.1f)));
        }
        return worst;
    };
    const float change = worstError(true), position = worstError(false);
    std::printf("between the trained points: change off by %.4f, position by %.4f\n", change, position);
    EXPECT_LT(change, 0.02f);  // measured 0.014 (four RBFs 0.4 apart: their sum dips between them)
    EXPECT_GT(position, 3.0f * change);  // measured 0.084
}

// A new state next to a well-known one shares some of its RBFs, but its own RBF was never trained:
// it must not look as certain as the known state. Trained only at x = 0 (x -> x), the model is
// certain there; at x = 0.2, half-way onto an RBF made but never trained, the uncertainty rises by
// that RBF's share of the activation.
TEST(PredictiveModel, StatesOnUntrainedRbfsAreNotCertain) {
    Fixture f(lineAgent());
    const auto known = f.features({}, {0.0f});
    const float stay = 0.0f;
    for (int i = 0; i < 50; ++i) f.model.train(f.weights, known, 0, nullptr, nullptr, &stay, 0.0f, f.model.rate(0.1f));
    const auto fresh = f.features({}, {0.2f});  // allocates an RBF at 0.2, one width away
    ASSERT_EQ(f.rep.featureCount(), 2u);
    Prediction atKnown, atFresh;
    f.model.predict(f.weights, known, 0, nullptr, atKnown);
    f.model.predict(f.weights, fresh, 0, nullptr, atFresh);
    EXPECT_LT(atKnown.uncertainty, 0.2f);
    float trainedShare = 0.0f, total = 0.0f;
    for (const auto& feature : fresh) {
        total += feature.activation;
        if (feature.index == known.front().index) trainedShare += feature.activation;
    }
    // Without the untrained RBF's share the old certainty would carry over (< 0.2).
    EXPECT_GT(atFresh.uncertainty, 1.0f - (1.0f - atKnown.uncertainty) * trainedShare / total - 0.05f);
    EXPECT_GT(atFresh.uncertainty, 0.4f);
}
