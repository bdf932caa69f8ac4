// Uses the installed static C++ libraries: an Agent, saved to a string and loaded back.
#include <cstdio>

#include "verve/agent.hpp"
#include "verve/io.hpp"

int main() {
    verve::AgentDescriptor desc;
    desc.addDiscreteSensor(4);
    desc.numActions = 3;
    verve::Agent agent(desc);
    verve::Observation obs(desc);
    for (int i = 0; i < 50; ++i) {
        obs.setDiscrete(0, i % 4);
        agent.update(i % 4 == 3 ? 1.0f : 0.0f, obs, 0.1f);
    }
    const std::string xml = verve::saveAgentToString(agent);
    const verve::Agent copy = verve::loadAgentFromMemory(xml.data(), xml.size());
    if (copy.rbfCount() != agent.rbfCount()) return 1;
    std::printf("consumer_cpp: ok (%zu features, save of %zu bytes)\n", copy.rbfCount(), xml.size());
    return 0;
}
