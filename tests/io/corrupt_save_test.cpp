// Bad saves are refused with a clear error naming what is wrong, and no agent.
#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <cmath>
#include <functional>

#include "io_test_support.hpp"
#include "xml_edit.hpp"
#include "verve/io.hpp"

namespace verve {
namespace {

class CorruptSave : public ::testing::Test {
protected:
    void SetUp() override {
        Agent agent = iotest::trainedAgent(iotest::mixedDescriptor(), 410);
        xml_ = saveAgentToString(agent);
    }

    // Edits the good save through pugixml and returns the result.
    std::string edited(const std::function<void(pugi::xml_node)>& edit) const { return iotest::editedXml(xml_, edit); }

    // Loading must throw `code` with a message containing `needle`.
    static void expectRefused(const std::string& data, ErrorCode code, const std::string& needle) {
        iotest::expectLoadRefused(data, code, needle);
    }

    // Replaces the first token of an element's number list.
    static void setFirstNumber(pugi::xml_node node, const std::string& value) {
        std::string text = node.text().get();
        const auto start = text.find_first_not_of(" \n");
        const auto end = text.find_first_of(" \n", start);
        node.text().set((text.substr(0, start) + value + text.substr(end)).c_str());
    }

    std::string xml_;
};

TEST_F(CorruptSave, EveryTruncationIsRefused) {
    // Cut at 300 points spread over the whole file (and just before the end).
    std::vector<std::size_t> cuts;
    for (std::size_t i = 0; i < 300; ++i) cuts.push_back(xml_.size() * i / 300);
    cuts.push_back(xml_.size() - 2);
    for (std::size_t cut : cuts) {
        const std::string part = xml_.substr(0, cut);
        try {
            loadAgentFromMemory(part.data(), part.size());
            ADD_FAILURE() << "a save cut at byte " << cut << " of " << xml_.size() << " loaded";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ErrorCode::Format) << e.what();
            EXPECT_GT(std::string(e.what()).size(), 20u);
        }
    }
}

TEST_F(CorruptSave, RandomByteDamageNeverCrashes) {
    // Any damage either still loads (e.g. a changed digit) or is refused with a verve::Error.
    std::uint64_t x = 88172645463325252ULL;
    auto next = [&x] {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        return x;
    };
    const char alphabet[] = "<>/=\" 0123456789.-eE nanif\n";
    int refused = 0;
    for (int round = 0; round < 1500; ++round) {
        std::string damaged = xml_;
        for (int k = 0, n = 1 + static_cast<int>(next() % 4); k < n; ++k) {
            damaged[next() % damaged.size()] = alphabet[next() % (sizeof alphabet - 1)];
        }
        try {
            loadAgentFromMemory(damaged.data(), damaged.size());
        } catch (const Error&) {
            ++refused;
        }
    }
    EXPECT_GT(refused, 100);
}

TEST_F(CorruptSave, TruncationIsNamed) {
    const std::string part = xml_.substr(0, xml_.size() / 2);
    expectRefused(part, ErrorCode::Format, "truncated");
    expectRefused("", ErrorCode::Format, "empty");
}

TEST_F(CorruptSave, NotXmlOrNotAnAgent) {
    expectRefused("hello, I am not XML", ErrorCode::Format, "XML");
    expectRefused("<?xml version=\"1.0\"?><scene/>", ErrorCode::Format, "root element is <scene>");
}

TEST_F(CorruptSave, FutureVersionIsAVersionError) {
    expectRefused(edited([](pugi::xml_node r) { r.attribute("format_version").set_value("6"); }),
                  ErrorCode::Version, "format version 6");
    expectRefused(edited([](pugi::xml_node r) { r.attribute("format_version").set_value("0"); }),
                  ErrorCode::Format, "format_version");
    expectRefused(edited([](pugi::xml_node r) { r.remove_attribute("format_version"); }),
                  ErrorCode::Format, "format_version");
}

TEST_F(CorruptSave, MissingPartsAreNamed) {
    expectRefused(edited([](pugi::xml_node r) { r.remove_child("weights"); }), ErrorCode::Format, "<weights>");
    expectRefused(edited([](pugi::xml_node r) { r.remove_child("descriptor"); }), ErrorCode::Format, "<descriptor>");
    expectRefused(edited([](pugi::xml_node r) { r.child("descriptor").remove_attribute("tau_value"); }),
                  ErrorCode::Format, "tau_value");
    expectRefused(edited([](pugi::xml_node r) { r.child("features").remove_child("centres"); }),
                  ErrorCode::Format, "<centres>");
}

TEST_F(CorruptSave, BadAttributeValuesAreNamed) {
    expectRefused(edited([](pugi::xml_node r) { r.child("descriptor").attribute("tau_value").set_value("fast"); }),
                  ErrorCode::Format, "tau_value");
    expectRefused(edited([](pugi::xml_node r) { r.child("descriptor").attribute("allocation").set_value("lazy"); }),
                  ErrorCode::Format, "allocation");
    expectRefused(edited([](pugi::xml_node r) { r.child("descriptor").attribute("actions").set_value("0"); }),
                  ErrorCode::Format, "num_actions");
    expectRefused(edited([](pugi::xml_node r) { r.child("state").attribute("learning").set_value("yes"); }),
                  ErrorCode::Format, "learning");
    expectRefused(edited([](pugi::xml_node r) { r.child("state").attribute("rng").set_value("0 0 0 0"); }),
                  ErrorCode::Format, "rng");
    expectRefused(edited([](pugi::xml_node r) { r.child("state").attribute("rng").set_value("1 2 3"); }),
                  ErrorCode::Format, "rng");
    expectRefused(edited([](pugi::xml_node r) { r.child("state").attribute("continuous_model").set_value("speed"); }),
                  ErrorCode::Format, "continuous_model");
    for (const char* range : {"reward_low=0.5", "reward_low=-1.5", "reward_high=-0.25", "reward_high=2", "reward_low=nan",
                              "final_reward_low=0.5", "final_reward_low=-1.5", "final_reward_high=-0.25",
                              "final_reward_high=2", "final_reward_high=nan"}) {
        const std::string edit = range;
        const std::string name = edit.substr(0, edit.find('='));
        const std::string value = edit.substr(edit.find('=') + 1);
        expectRefused(edited([&](pugi::xml_node r) { r.child("state").attribute(name.c_str()).set_value(value.c_str()); }),
                      ErrorCode::Format, "reward range");
    }
}

TEST_F(CorruptSave, NumbersMustBeFinite) {
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("weights"), "nan"); }),
                  ErrorCode::Format, "weights[0] is not a finite number");
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("weights"), "inf"); }),
                  ErrorCode::Format, "weights[0]");
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("weights"), "0.5.5"); }),
                  ErrorCode::Format, "'0.5.5'");
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("traces").child("values"), "-inf"); }),
                  ErrorCode::Format, "traces[0]");
}

// A weight no learning reaches is refused: from the ones a fuzzer found (1e28 to 4e33) one update
// overflowed a model weight to inf, and the agent could then no longer be saved.
TEST_F(CorruptSave, WeightsBeyondWhatLearningReachesAreRefused) {
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("weights"), "3.8e33"); }),
                  ErrorCode::Format, "beyond +-1e20");
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("weights"), "-2e20"); }),
                  ErrorCode::Format, "beyond +-1e20");
}

// An activation beyond 1 scaled a fuzzed save's first update until model weights reached 1e23.
TEST_F(CorruptSave, PreviousActivationsMustLieWithinZeroAndOne) {
    for (const char* bad : {"1e20", "-0.5", "1.5"}) {
        expectRefused(edited([bad](pugi::xml_node r) { setFirstNumber(r.child("previous").child("activations"), bad); }),
                      ErrorCode::Format, "outside [0, 1]");
    }
}

TEST_F(CorruptSave, WeightsAtTheLimitStillLearnAndSave) {
    AgentDescriptor d = iotest::plannerDescriptor();
    AgentSnapshot snap = iotest::trainedAgent(d, 60).snapshot();
    for (std::size_t i = 0; i < snap.weights.size(); ++i) {
        snap.weights[i] = (i % 3 == 0 ? -1.0f : 1.0f) * AgentSnapshot::kWeightLimit;
    }
    Agent agent(snap);
    iotest::Feed feed(9);
    iotest::drive(agent, feed, 200);
    for (float w : agent.snapshot().weights) ASSERT_TRUE(std::isfinite(w));
    const std::string saved = saveAgentToString(agent);  // and it loads again
    EXPECT_NO_THROW(loadAgentFromMemory(saved.data(), saved.size()));
}

TEST_F(CorruptSave, SizesMustMatchTheDescriptor) {
    expectRefused(edited([](pugi::xml_node r) { r.child("weights").attribute("stride").set_value("3"); }),
                  ErrorCode::Format, "weights holds");
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("features").child("keys"), ""); }),
                  ErrorCode::Format, "count=");
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("features").child("centres"), ""); }),
                  ErrorCode::Format, "centres holds");
    expectRefused(edited([](pugi::xml_node r) {
                      // One continuous sensor fewer: the centres no longer fit the descriptor.
                      r.child("descriptor").remove_child("continuous_sensor");
                  }),
                  ErrorCode::Format, "centres holds");
}

TEST_F(CorruptSave, IndicesMustBeInRange) {
    // 3 discrete combinations in each of 2 lattices (the sensors' and its fine one): keys 0-5.
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("features").child("keys"), "6"); }),
                  ErrorCode::Format, "featureKeys[0] = 6 is out of range");
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("features").child("centres"), "1.5"); }),
                  ErrorCode::Format, "centres[0]");
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("traces").child("features"), "999999"); }),
                  ErrorCode::Format, "traceFeatures[0]");
    expectRefused(edited([](pugi::xml_node r) { r.child("previous").attribute("action").set_value("3"); }),
                  ErrorCode::Format, "previousAction");
    expectRefused(edited([](pugi::xml_node r) { setFirstNumber(r.child("previous").child("discrete"), "-1"); }),
                  ErrorCode::Format, "previousDiscrete[0]");
}

TEST_F(CorruptSave, TheCoreChecksWhatIoCannot) {
    // A stride that matches the weight count but not the descriptor (3 actions need stride 4).
    std::string bad = edited([](pugi::xml_node r) {
        pugi::xml_node w = r.child("weights");
        // Keep every number but declare them rows of 2: count x 4 == (count * 2) x 2.
        w.attribute("stride").set_value("2");
        pugi::xml_node f = r.child("features");
        const std::string keys = f.child("keys").text().get();
        f.child("keys").text().set((keys + " " + keys).c_str());
        f.attribute("count").set_value(std::to_string(2 * std::stoul(f.attribute("count").value())).c_str());
        const std::string centres = f.child("centres").text().get();
        f.child("centres").text().set((centres + " " + centres).c_str());
    });
    expectRefused(bad, ErrorCode::Format, "stride");
}

}  // namespace
}  // namespace verve
