// The message validate() gives a descriptor in the C ABI's field names ("" when it is valid),
// shared by the core tests of descriptor checks.
#pragma once
#include <string>

#include "verve/agent_descriptor.hpp"
#include "verve/error.hpp"

namespace verve::coretest {

inline std::string validationError(const AgentDescriptor& d) {
    try {
        d.validate(FieldNaming::CAbi);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace verve::coretest
