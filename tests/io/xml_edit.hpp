// Edited XML saves and the refusal a bad one must meet: the corrupt-save tests' two helpers.
#pragma once
#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <functional>
#include <sstream>
#include <string>

#include "verve/error.hpp"
#include "verve/io.hpp"

namespace verve::iotest {

// `xml` edited through pugixml (`edit` gets the document element).
inline std::string editedXml(const std::string& xml, const std::function<void(pugi::xml_node)>& edit) {
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_string(xml.c_str()));
    edit(doc.document_element());
    std::ostringstream out;
    doc.save(out);
    return out.str();
}

// Loading `data` must throw `code` with a message containing `needle`.
inline void expectLoadRefused(const std::string& data, ErrorCode code, const std::string& needle) {
    try {
        loadAgentFromMemory(data.data(), data.size());
        ADD_FAILURE() << "loaded a bad save; expected an error containing '" << needle << "'";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), code) << e.what();
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what() << " (expected '" << needle << "')";
    }
}

}  // namespace verve::iotest
