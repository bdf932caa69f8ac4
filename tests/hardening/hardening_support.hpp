// Helpers shared by the hardening suites: agents through the C ABI and textual save edits.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "verve_c.h"

namespace verve::hardening {

inline std::string lastError() { return verve_last_error(); }

// One discrete sensor (3 values), two continuous ones (the first circular), three actions; with
// planning, novelty curiosity too: every part of an agent that allocates.
inline verve_agent_desc mixedDesc(bool planning, uint64_t seed = 1) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    d.num_discrete_sensors = 1;
    d.discrete_sensor_values[0] = 3;
    d.num_continuous_sensors = 2;
    d.continuous_sensor_circular[0] = 1;
    d.num_actions = 3;
    d.planning = planning ? 1 : 0;
    d.curiosity = planning ? VERVE_CURIOSITY_NOVELTY : VERVE_CURIOSITY_NONE;
    d.seed = seed;
    return d;
}

inline verve_agent* createOrFail(const verve_agent_desc& d) {
    verve_agent* agent = nullptr;
    EXPECT_EQ(verve_agent_create(&d, &agent), VERVE_OK) << verve_last_error();
    return agent;
}

inline std::string saveToString(const verve_agent* agent) {
    size_t size = 0;
    EXPECT_EQ(verve_agent_save_memory(agent, nullptr, &size), VERVE_OK) << verve_last_error();
    std::string xml(size, '\0');
    EXPECT_EQ(verve_agent_save_memory(agent, &xml[0], &size), VERVE_OK) << verve_last_error();
    xml.resize(size);
    return xml;
}

// The first <element ... attribute="..."> gets a new value.
inline std::string replaceAttribute(std::string xml, const std::string& element, const std::string& attribute,
                                    const std::string& value) {
    const auto at = xml.find("<" + element);
    const auto key = xml.find(" " + attribute + "=\"", at);
    const auto start = key + attribute.size() + 3;
    xml.replace(start, xml.find('"', start) - start, value);
    return xml;
}

// Every number listed in <element ...>...</element> becomes `value`.
inline std::string replaceList(const std::string& xml, const std::string& element, const std::string& value) {
    const auto open = xml.find('>', xml.find("<" + element)) + 1;
    const auto close = xml.find("</" + element + ">", open);
    std::string out = xml.substr(0, open);
    bool inNumber = false;
    for (auto i = open; i < close; ++i) {
        const bool space = xml[i] == ' ' || xml[i] == '\n';
        if (space) out += xml[i];
        else if (!inNumber) out += value;
        inNumber = !space;
    }
    return out + xml.substr(close);
}

}  // namespace verve::hardening
