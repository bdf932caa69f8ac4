// Saves keep the lattices they were made with (core/fine_lattice.hpp): an agent with the fine
// lattice loads with it, one made without it (as every save from before it) loads without it.
#include <gtest/gtest.h>

#include <string>

#include "verve/agent.hpp"
#include "verve/io.hpp"

using namespace verve;

TEST(FineLatticeSave, SavesKeepTheLatticesTheyWereMadeWith) {
    for (bool fine : {true, false}) {
        AgentDescriptor d;
        d.addContinuousSensor().addContinuousSensor();
        if (!fine) d.adaptation &= ~Adaptation::FineLattice;
        Agent agent(d);
        Observation o(d);
        for (int i = 0; i < 40; ++i) {
            o.continuous = {0.05f * static_cast<float>(i % 20) - 0.5f, 0.3f};
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
                o.continuous = {0.9f - 0.06f * static_cast<float>(i), -0.7f};
                EXPECT_EQ(loaded.update(0.0f, o, 0.1f), original.update(0.0f, o, 0.1f));
            }
            EXPECT_EQ(loaded.rbfCount(), original.rbfCount());
        }
    }
}
