// Floats as text through std::to_chars / std::from_chars: the shortest text that reads back to the
// same bits, independent of the C locale. Used wherever the standard library has the float
// overloads (GCC 11+, MSVC); float_text_libc.cpp stands in where it does not (Emscripten's libc++).
#include <charconv>

#include "io/number_text.hpp"

namespace verve::io {

void appendNumber(std::string& out, float value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

bool parseNumber(std::string_view text, float& out) {
    // std::from_chars also reads "inf"/"nan"; they are parsed here and refused by the validator,
    // which can then say which field holds them. It accepts neither a leading '+' nor whitespace.
    if (text.empty()) return false;
    float value{};
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return false;
    out = value;
    return true;
}

}  // namespace verve::io
