// Tests for core/heat_map.*: black for identical pixels, the inferno stops at the
// stated differences, saturation at 8/255, and a linear image that displays as the ramp.
#include <cmath>

#include <gtest/gtest.h>

#include "image/heat_map.h"
#include "image/image_compare.h"
#include "image/srgb.h"

namespace whitted {
namespace {

// Rec. 709 luma of a display colour: the ramp must get lighter as differences grow.
float luma(glm::vec3 c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

TEST(HeatMapColour, ZeroIsBlack_EightStepsAndMoreIsTheTop) {
    EXPECT_EQ(heatMapColour(0.0f), glm::vec3(0.0f));
    const glm::vec3 top = heatMapColour(kHeatMapSaturation);
    EXPECT_NEAR(top.r, 0.988362f, 1e-6f);
    EXPECT_NEAR(top.g, 0.998364f, 1e-6f);
    EXPECT_NEAR(top.b, 0.644924f, 1e-6f);
    EXPECT_EQ(heatMapColour(0.5f), top);
    EXPECT_EQ(heatMapColour(1.0f), top);
    // Half way (4/255) is inferno's middle.
    const glm::vec3 mid = heatMapColour(4.0f / 255.0f);
    EXPECT_NEAR(mid.r, 0.735683f, 1e-5f);
    EXPECT_NEAR(mid.g, 0.215906f, 1e-5f);
    EXPECT_NEAR(mid.b, 0.330245f, 1e-5f);
}

TEST(HeatMapColour, LightnessRisesWithTheDifference) {
    float last = -1.0f;
    for (int i = 0; i <= 800; ++i) {
        const float l = luma(heatMapColour(i / 100.0f / 255.0f));
        EXPECT_GE(l, last) << "difference " << i / 100.0 << "/255";
        last = l;
    }
    // One 8-bit step already stands out from black.
    EXPECT_GT(luma(heatMapColour(1.0f / 255.0f)), 0.04f);
}

TEST(HeatMap, IdenticalImages_AllBlack) {
    Image a(7, 5);
    for (std::size_t i = 0; i < a.rgb.size(); ++i) a.rgb[i] = float(i % 11) / 10.0f;
    const Image h = heatMap(a, a);
    ASSERT_EQ(h.width, 7);
    ASSERT_EQ(h.height, 5);
    for (float v : h.rgb) ASSERT_EQ(v, 0.0f);
}

TEST(HeatMap, DisplaysAsTheRampOfEachPixelsDifference) {
    Image a(3, 1), b(3, 1);
    // Pixel 0 the same; pixel 1 differs by 4/255 in green; pixel 2 by a lot.
    a.pixel(1, 0)[1] = srgbDecode8(100);
    b.pixel(1, 0)[1] = srgbDecode8(104);
    b.pixel(2, 0)[0] = 1.0f;
    const Image h = heatMap(a, b);
    for (int x = 0; x < 3; ++x) {
        const glm::vec3 want = heatMapColour(displayDifference(a.pixel(x, 0), b.pixel(x, 0)));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(srgbEncode(h.pixel(x, 0)[c]), want[c], 1e-5f) << x << ", " << c;
    }
    EXPECT_EQ(h.pixel(0, 0)[0], 0.0f);
    EXPECT_THROW(heatMap(a, Image(2, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace whitted
