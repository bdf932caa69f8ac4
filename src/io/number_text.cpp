#include "io/number_text.hpp"

// Floats are in float_text_charconv.cpp or float_text_libc.cpp (src/CMakeLists.txt picks one).

#include <charconv>
#include <cmath>
#include <limits>
#include <type_traits>

namespace verve::io {
namespace {

template <typename T>
void appendWithToChars(std::string& out, T value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

template <typename T>
bool parseWithFromChars(std::string_view text, T& out) {
    if (text.empty()) return false;
    // from_chars accepts neither a leading '+' nor leading whitespace; the format never writes them.
    T value{};
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return false;
    out = value;
    return true;
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

void appendNumber(std::string& out, std::uint64_t value) { appendWithToChars(out, value); }
void appendNumber(std::string& out, std::int64_t value) { appendWithToChars(out, value); }

std::string numberText(float value) {
    std::string s;
    appendNumber(s, value);
    return s;
}

std::string numberText(std::uint64_t value) {
    std::string s;
    appendNumber(s, value);
    return s;
}

bool parseNumber(std::string_view text, std::uint64_t& out) { return parseWithFromChars(text, out); }
bool parseNumber(std::string_view text, std::int64_t& out) { return parseWithFromChars(text, out); }

template <typename T>
bool parseList(std::string_view text, std::vector<T>& out, std::string& badToken) {
    out.clear();
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && isSpace(text[i])) ++i;
        const std::size_t start = i;
        while (i < text.size() && !isSpace(text[i])) ++i;
        if (start == i) break;
        const std::string_view token = text.substr(start, i - start);
        T value{};
        bool ok = false;
        if constexpr (std::is_same_v<T, float>) {
            ok = parseNumber(token, value);
        } else if constexpr (std::is_signed_v<T>) {
            std::int64_t wide = 0;
            ok = parseNumber(token, wide) && wide >= std::numeric_limits<T>::min() &&
                 wide <= std::numeric_limits<T>::max();
            value = static_cast<T>(wide);
        } else {
            std::uint64_t wide = 0;
            ok = parseNumber(token, wide) && wide <= std::numeric_limits<T>::max();
            value = static_cast<T>(wide);
        }
        if (!ok) {
            badToken.assign(token.substr(0, 40));
            return false;
        }
        out.push_back(value);
    }
    return true;
}

template bool parseList<float>(std::string_view, std::vector<float>&, std::string&);
template bool parseList<std::uint64_t>(std::string_view, std::vector<std::uint64_t>&, std::string&);
template bool parseList<std::uint32_t>(std::string_view, std::vector<std::uint32_t>&, std::string&);
template bool parseList<std::int32_t>(std::string_view, std::vector<std::int32_t>&, std::string&);

}  // namespace verve::io
