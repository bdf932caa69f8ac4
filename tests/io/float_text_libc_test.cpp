// float_text_libc.cpp, the web build's floats as text, against std::to_chars / from_chars on the
// native build: what it writes reads back to the same bits with from_chars (a web save loads
// natively), what to_chars writes reads back with it (a native save loads on the web), and it
// accepts exactly the tokens from_chars accepts. Linked into verve_float_text_libc_tests with
// number_text_test.cpp, whose tests then run on this implementation too.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <string>

#include "io/number_text.hpp"

namespace verve::io {
namespace {

bool fromChars(const std::string& text, float& out) {
    if (text.empty()) return false;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), out);
    return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(FloatTextLibc, ReadsWhatToCharsWritesAndFromCharsReadsWhatItWrites) {
    std::uint32_t x = 987654321;
    for (int i = 0; i < 300000; ++i) {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        float v;
        std::memcpy(&v, &x, sizeof v);
        if (std::isnan(v)) continue;
        const std::string ours = numberText(v);
        float back = 0.0f;
        ASSERT_TRUE(fromChars(ours, back)) << ours;
        ASSERT_TRUE(sameBits(back, v)) << ours;
        char buffer[64];
        const auto written = std::to_chars(buffer, buffer + sizeof buffer, v);
        const std::string theirs(buffer, written.ptr);
        ASSERT_TRUE(parseNumber(theirs, back)) << theirs;
        ASSERT_TRUE(sameBits(back, v)) << theirs;
        ASSERT_LE(ours.size(), theirs.size() + 4) << ours << " against " << theirs;  // no longer than needed
    }
}

TEST(FloatTextLibc, AcceptsWhatFromCharsAccepts) {
    const char* tokens[] = {
        "0", "-0", "1", "-1", "1.5", ".5", "5.", "-.5", "1e5", "1E5", "1e+5", "1e-5", "-2.5e-3", "1e", "1e+",
        "e5", ".", "-", "+1", " 1", "1 ", "1,5", "0x1p3", "0x10", "1f", "inf", "-inf", "INF", "infinity",
        "-Infinity", "nan", "NaN", "-nan", "infx", "1e39", "-1e39", "1e-39", "1e-45", "1e-46", "1e-50",
        "3.4028235e38", "3.4028236e38", "00012", "1..2", "1e5.5", "--1", "1-", "12345678901234567890",
        "0.000000000000000000000000000000000000000000001",
    };
    for (const char* token : tokens) {
        float ours = 0.0f;
        float theirs = 0.0f;
        const bool weAccept = parseNumber(token, ours);
        const bool theyAccept = fromChars(token, theirs);
        EXPECT_EQ(weAccept, theyAccept) << "'" << token << "'";
        if (weAccept && theyAccept && !std::isnan(theirs)) {
            EXPECT_TRUE(sameBits(ours, theirs)) << "'" << token << "'";
        }
    }
}

}  // namespace
}  // namespace verve::io
