// Floats as text through the C library, for standard libraries without std::to_chars /
// std::from_chars for floats (Emscripten's libc++; src/CMakeLists.txt checks). Same contract as
// float_text_charconv.cpp: the text reads back to the same bits, and parsing takes exactly what
// from_chars takes (no '+', no whitespace, no hex, "inf"/"nan" read for the validator to refuse).
// The text may be spelled differently from to_chars's ("0.0001" for its "1e-04"); both builds read
// both. snprintf and strtof follow the C locale: this file is only for C libraries that have just
// the "C" locale, as Emscripten's musl does in the browser.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "io/number_text.hpp"

namespace verve::io {
namespace {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool isWord(std::string_view text) {  // from_chars's spellings of infinity and NaN
    if (!text.empty() && text.front() == '-') text.remove_prefix(1);
    std::string lower(text);
    for (char& c : lower) c = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    return lower == "inf" || lower == "infinity" || lower == "nan";
}

}  // namespace

void appendNumber(std::string& out, float value) {
    char buffer[64];
    if (std::isnan(value)) {
        out.append(std::signbit(value) ? "-nan" : "nan");
        return;
    }
    // The fewest significant digits that read back to the same float (9 always do).
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, static_cast<double>(value));
        if (sameBits(std::strtof(buffer, nullptr), value)) break;
    }
    out.append(buffer);
}

bool parseNumber(std::string_view text, float& out) {
    if (text.empty() || text.size() > 200) return false;
    if (!isWord(text)) {
        for (const char c : text) {
            const bool allowed = (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '-' || c == '+';
            if (!allowed) return false;
        }
        if (text.front() == '+') return false;
    }
    const std::string copy(text);  // strtof needs the terminating zero
    char* end = nullptr;
    errno = 0;
    const float value = std::strtof(copy.c_str(), &end);
    if (end != copy.c_str() + copy.size()) return false;
    // Out of range: refused as from_chars refuses it (overflow, or a non-zero text that reads as 0);
    // a subnormal result is a float that to_chars writes, so it reads back.
    if (errno == ERANGE && (std::isinf(value) || value == 0.0f)) return false;
    out = value;
    return true;
}

}  // namespace verve::io
