// srgbEncode8 answers from a table of thresholds; it must give exactly the
// codes of the formula lround(srgbEncode(x) * 255) that SPEC §5 describes.
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "image/srgb.h"

namespace whitted {
namespace {

std::uint8_t byFormula(float x) {
    return static_cast<std::uint8_t>(std::lround(srgbEncode(x) * 255.0f));
}

TEST(Srgb, Encode8EqualsFormulaOnEveryFloatFromZeroToOne) {
    // Every 7th float bit pattern in [0, 1]: about 150 million values would be
    // slow; a stride still lands on both sides of every threshold many times.
    int checked = 0;
    for (std::uint32_t bits = 0; bits <= 0x3f800000u; bits += 7) {
        float x;
        std::memcpy(&x, &bits, sizeof x);
        ASSERT_EQ(srgbEncode8(x), byFormula(x)) << "x = " << x;
        ++checked;
    }
    EXPECT_GT(checked, 100000000);
}

// The adaptive render's estimates take codes from srgbEncodeFast(): a
// four-hundredth of a code from the formula is far below what they measure.
TEST(Srgb, FastEncodeIsWithinAFourHundredthOfACodeOfTheFormula) {
    double worst = 0.0;
    for (std::uint32_t bits = 0; bits <= 0x3f800000u; bits += 997) {
        float x;
        std::memcpy(&x, &bits, sizeof x);
        worst = std::max(worst, std::fabs(double(srgbEncodeFast(x)) - double(srgbEncode(x))));
    }
    EXPECT_LT(worst * 255.0, 0.0025);
    EXPECT_GT(worst, 0.0);  // it interpolates: not the formula itself
    EXPECT_EQ(srgbEncodeFast(-1.0f), 0.0f);
    EXPECT_EQ(srgbEncodeFast(std::nanf("")), 0.0f);
    EXPECT_EQ(srgbEncodeFast(-std::nanf("")), 0.0f);
    EXPECT_EQ(srgbEncodeFast(-0.0f), 0.0f);
    EXPECT_EQ(srgbEncodeFast(-INFINITY), 0.0f);
    EXPECT_EQ(srgbEncodeFast(1.0f), 1.0f);
    EXPECT_EQ(srgbEncodeFast(INFINITY), 1.0f);
    EXPECT_NEAR(srgbEncodeFast(0.5f) * 255.0f, 187.52f, 0.01f);
}

TEST(Srgb, Encode8ClampsAndHandlesOddInputs) {
    EXPECT_EQ(srgbEncode8(-1.0f), 0);
    EXPECT_EQ(srgbEncode8(0.0f), 0);
    EXPECT_EQ(srgbEncode8(std::nanf("")), 0);
    EXPECT_EQ(srgbEncode8(1.0f), 255);
    EXPECT_EQ(srgbEncode8(7.5f), 255);
    EXPECT_EQ(srgbEncode8(INFINITY), 255);
    // Linear 0.5 is sRGB 1.055 * 0.5^(1/2.4) - 0.055 = 0.73536, times 255 = 187.52.
    EXPECT_EQ(srgbEncode8(0.5f), 188);
}

TEST(Srgb, DecodeThenEncodeGivesTheSameCode) {
    for (int code = 0; code < 256; ++code)
        EXPECT_EQ(srgbEncode8(srgbDecode8(static_cast<std::uint8_t>(code))), code) << code;
}

// The row forms give what the single ones give, value for value, odd inputs too.
TEST(Srgb, RowFormsEqualTheSingleOnes) {
    std::vector<float> values = {-1.0f, 0.0f, -0.0f,    std::nanf(""), -std::nanf(""),
                                 1.0f,  7.5f, INFINITY, -INFINITY,     0.5f};
    for (std::uint32_t bits = 0; bits <= 0x3f800000u; bits += 1009) {
        float x;
        std::memcpy(&x, &bits, sizeof x);
        values.push_back(x);
    }
    std::vector<std::uint8_t> codes(values.size());
    std::vector<float> encoded(values.size());
    srgbEncode8(values.data(), values.size(), codes.data());
    srgbEncodeFast(values.data(), values.size(), encoded.data());
    for (std::size_t i = 0; i < values.size(); ++i) {
        ASSERT_EQ(codes[i], srgbEncode8(values[i])) << "x = " << values[i];
        ASSERT_EQ(encoded[i], srgbEncodeFast(values[i])) << "x = " << values[i];
    }
    EXPECT_GT(values.size(), 1000000u);
}

}  // namespace
}  // namespace whitted
