// Saves of agents that learn a rate per sensor group (core/group_rates.hpp): the rates and the
// history travel in both formats and the loaded agent goes on exactly as the original; a save
// without them starts them afresh; bad values are refused, naming what is wrong.
#include <gtest/gtest.h>
#include <pugixml.hpp>

#include "io_test_support.hpp"
#include "xml_edit.hpp"
#include "verve/io.hpp"

namespace verve {
namespace {

Agent groupedAgent() { return iotest::trainedAgent(iotest::groupedDescriptor(), 410); }

using iotest::editedXml;

void expectRefused(const std::string& data, const std::string& needle) {
    iotest::expectLoadRefused(data, ErrorCode::Format, needle);
}

TEST(GroupRatesSave, BothFormatsKeepTheRatesAndTheFuture) {
    Agent agent = groupedAgent();
    const AgentSnapshot snap = agent.snapshot();
    ASSERT_EQ(snap.groupLogRates.size(), 11u);  // 6 continuous sensors: 6 singles, 5 pairs
    ASSERT_EQ(snap.groupHistory.size(), snap.featureKeys.size());
    bool moved = false;
    for (float r : snap.groupLogRates) moved = moved || r != 0.0f;
    EXPECT_TRUE(moved) << "410 steps left every rate where it began";
    for (SaveFormat format : {SaveFormat::Xml, SaveFormat::Binary}) {
        const std::string bytes = saveAgentToString(agent, SaveOptions{true, format});
        Agent loaded = loadAgentFromMemory(bytes.data(), bytes.size());
        iotest::expectSameSnapshot(snap, loaded.snapshot());
        Agent original = loadAgentFromMemory(bytes.data(), bytes.size());
        iotest::expectSameFuture(original, loaded);
    }
}

TEST(GroupRatesSave, WithoutThemTheRatesStartAfreshAndWithoutTheBitThereAreNone) {
    Agent agent = groupedAgent();
    const std::string xml = saveAgentToString(agent);
    const std::string bare = editedXml(xml, [](pugi::xml_node r) { r.remove_child("group_rates"); });
    const AgentSnapshot fresh = loadAgentFromMemory(bare.data(), bare.size()).snapshot();
    EXPECT_EQ(fresh.groupLogRates, std::vector<float>(11, 0.0f));
    EXPECT_EQ(fresh.groupHistory, std::vector<float>(fresh.featureKeys.size(), 0.0f));
    // A save made without the adaptation (as every save before it): one rate for all, as then.
    AgentDescriptor d = iotest::groupedDescriptor();
    d.adaptation &= ~Adaptation::GroupRates;
    const std::string older = saveAgentToString(iotest::trainedAgent(d, 200));
    EXPECT_EQ(older.find("group_rates"), std::string::npos);
    EXPECT_TRUE(loadAgentFromMemory(older.data(), older.size()).snapshot().groupLogRates.empty());
    // ... and such an agent refuses rates put into its save, even of the right sizes.
    const std::string grafted = editedXml(older, [](pugi::xml_node r) {
        const std::string features = r.child("features").attribute("count").value();
        std::string zeros;
        for (int i = 0; i < std::stoi(features); ++i) zeros += "0 ";
        pugi::xml_node g = r.append_child("group_rates");
        g.append_child("log_rates").text().set("0 0 0 0 0 0 0 0 0 0 0");
        g.append_child("norms").text().set("0 0 0 0 0 0 0 0 0 0 0");
        g.append_child("history").text().set(zeros.c_str());
    });
    expectRefused(grafted, "group rates are saved for an agent without");
}

TEST(GroupRatesSave, BadValuesAndSizesAreRefused) {
    const std::string xml = saveAgentToString(groupedAgent());
    const auto withList = [&](const char* list, const char* text) {
        return editedXml(xml, [&](pugi::xml_node r) { r.child("group_rates").child(list).text().set(text); });
    };
    expectRefused(withList("log_rates", "7 0 0 0 0 0 0 0 0 0 0"), "log rate lies beyond +-6");
    expectRefused(withList("log_rates", "0 0 0"), "groupNorms holds 11 values, expected 3");
    expectRefused(withList("norms", "-1 0 0 0 0 0 0 0 0 0 0"), "norm is negative");
    expectRefused(withList("norms", "nan 0 0 0 0 0 0 0 0 0 0"), "groupNorms");
    expectRefused(withList("history", "0 0"), "groupHistory holds 2 values");
    const std::string huge = editedXml(xml, [](pugi::xml_node r) {
        pugi::xml_node h = r.child("group_rates").child("history");
        std::string text = h.text().get();
        const auto start = text.find_first_not_of(" \n");
        const auto end = text.find_first_of(" \n", start);
        h.text().set((text.substr(0, start) + "2e6" + text.substr(end)).c_str());
    });
    expectRefused(huge, "group history lies beyond +-1e6");
}

}  // namespace
}  // namespace verve
