// Numbers as text for the XML format: exact float round-trips (shortest form that reads back to the
// same bits) and strict parsing, both independent of the host's C locale (an engine may have set
// one with a decimal comma).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace verve::io {

void appendNumber(std::string& out, float value);
void appendNumber(std::string& out, std::uint64_t value);
void appendNumber(std::string& out, std::int64_t value);
std::string numberText(float value);
std::string numberText(std::uint64_t value);

// Parse one whole token; false if it is not exactly a number of that type (or out of range).
bool parseNumber(std::string_view text, float& out);
bool parseNumber(std::string_view text, std::uint64_t& out);
bool parseNumber(std::string_view text, std::int64_t& out);

// Whitespace-separated list. On failure returns false and `badToken` holds the offending text.
template <typename T>
bool parseList(std::string_view text, std::vector<T>& out, std::string& badToken);

}  // namespace verve::io
