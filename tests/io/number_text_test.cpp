// Numbers in the XML format: every finite float survives text exactly; parsing is strict.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "io/number_text.hpp"

namespace verve::io {
namespace {

bool roundTrips(float value) {
    float back = 0.0f;
    if (!parseNumber(numberText(value), back)) return false;
    return std::memcmp(&value, &back, sizeof value) == 0;
}

TEST(NumberText, SpecialFloatsRoundTripBitForBit) {
    const float cases[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.1f, 1.0f / 3.0f, 2.0f / 3.0f, 1e-45f,
                           std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(),
                           std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest(),
                           std::numeric_limits<float>::epsilon(), 16777217.0f, 3.14159274f};
    for (float v : cases) EXPECT_TRUE(roundTrips(v)) << numberText(v);
}

TEST(NumberText, RandomBitPatternsRoundTripBitForBit) {
    std::uint32_t x = 12345;
    int tested = 0;
    for (int i = 0; i < 200000; ++i) {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        float v;
        std::memcpy(&v, &x, sizeof v);
        if (!std::isfinite(v)) continue;
        ++tested;
        ASSERT_TRUE(roundTrips(v)) << "bits " << x << " text " << numberText(v);
    }
    EXPECT_GT(tested, 190000);
}

TEST(NumberText, IntegersRoundTrip) {
    std::uint64_t back = 0;
    ASSERT_TRUE(parseNumber(numberText(std::numeric_limits<std::uint64_t>::max()), back));
    EXPECT_EQ(back, std::numeric_limits<std::uint64_t>::max());
    EXPECT_FALSE(parseNumber("18446744073709551616", back));  // 2^64
    EXPECT_FALSE(parseNumber("-1", back));
}

TEST(NumberText, ParsingIsStrict) {
    float f = 0.0f;
    EXPECT_FALSE(parseNumber("", f));
    EXPECT_FALSE(parseNumber("1.5x", f));
    EXPECT_FALSE(parseNumber(" 1.5", f));
    EXPECT_FALSE(parseNumber("1,5", f));
    EXPECT_FALSE(parseNumber("abc", f));
    EXPECT_TRUE(parseNumber("-2.5e-3", f));
    EXPECT_EQ(f, -2.5e-3f);
}

TEST(NumberText, ListsReportTheBadToken) {
    std::vector<std::uint32_t> values;
    std::string bad;
    EXPECT_TRUE(parseList<std::uint32_t>(" 1 2\n3\t4 ", values, bad));
    EXPECT_EQ(values, (std::vector<std::uint32_t>{1, 2, 3, 4}));
    EXPECT_FALSE(parseList<std::uint32_t>("1 2 4294967296 3", values, bad));  // 2^32 does not fit
    EXPECT_EQ(bad, "4294967296");
    std::vector<std::int32_t> signedValues;
    EXPECT_TRUE(parseList<std::int32_t>("-3 0 7", signedValues, bad));
    EXPECT_EQ(signedValues, (std::vector<std::int32_t>{-3, 0, 7}));
}

}  // namespace
}  // namespace verve::io
