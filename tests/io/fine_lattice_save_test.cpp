// Saves keep the lattices they were made with (core/lattice_layout.hpp): an agent with the fine
// lattice, or with groups beside its lattice, loads with them; one made without them (as every
// save from before them) loads without them.
#include <gtest/gtest.h>

#include <string>

#include "verve/agent.hpp"
#include "verve/io.hpp"

using namespace verve;

namespace {

// Plays d's agent on a path over its continuous sensors, saves it in both formats, and checks the
// loaded agent saves the same bytes and plays on exactly as the original does.
void expectSavesKeepTheLattices(const AgentDescriptor& d) {
    const std::size_t n = d.continuousSensors.size();
    Agent agent(d);
    Observation o(d);
    for (int i = 0; i < 40; ++i) {
        for (std::size_t s = 0; s < n; ++s) o.continuous[s] = s == 0 ? 0.05f * static_cast<float>(i % 20) - 0.5f : 0.3f - 0.1f * s;
        agent.update(i % 7 == 0 ? 1.0f : 0.0f, o, 0.1f);
    }
    for (SaveFormat format : {SaveFormat::Xml, SaveFormat::Binary}) {
        SaveOptions options;
        options.format = format;
        const std::string bytes = saveAgentToString(agent, options);
        Agent loaded = loadAgentFromMemory(bytes.data(), bytes.size());
        EXPECT_EQ(loaded.rbfCount(), agent.rbfCount());
        EXPECT_EQ(loaded.descriptor().adaptation, d.adaptation);
        EXPECT_EQ(saveAgentToString(loaded, options), bytes);
        Agent original = loadAgentFromMemory(bytes.data(), bytes.size());
        for (int i = 0; i < 30; ++i) {
            for (std::size_t s = 0; s < n; ++s) o.continuous[s] = s == 0 ? 0.9f - 0.06f * static_cast<float>(i) : -0.7f;
            EXPECT_EQ(loaded.update(0.0f, o, 0.1f), original.update(0.0f, o, 0.1f));
        }
        EXPECT_EQ(loaded.rbfCount(), original.rbfCount());
    }
}

}  // namespace

TEST(FineLatticeSave, SavesKeepTheLatticesTheyWereMadeWith) {
    for (bool fine : {true, false}) {
        AgentDescriptor d;
        d.addContinuousSensor().addContinuousSensor();
        if (!fine) d.adaptation &= ~Adaptation::FineLattice;
        expectSavesKeepTheLattices(d);
    }
}

TEST(PairsBesideSave, SavesKeepTheLatticesTheyWereMadeWith) {
    for (bool beside : {true, false}) {
        AgentDescriptor d;
        d.addContinuousSensor().addContinuousSensor().addContinuousSensor().addContinuousSensor();
        if (!beside) d.adaptation &= ~Adaptation::PairsBeside;
        expectSavesKeepTheLattices(d);
    }
}
