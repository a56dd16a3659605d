// The editor's float-range warning fires exactly outside the range the sweep
// measured (docs/numerics.md): the seed scaled by 10^k is fine in float for
// k in [-20, 14] and wrong at 10^15 and 10^-25.
#include <gtest/gtest.h>

#include "analysis/float_range.h"
#include "scene/scene_transform.h"
#include "support/core_support.h"

namespace whitted {
namespace {

TEST(FloatRange, SeedAndItsMeasuredScalesAreInside) {
    for (double factor : {1.0, 1e-20, 1e-4, 1e4, 1e14}) {
        EXPECT_FALSE(floatRangeProblem(scaledScene(test::seedScene(), factor))) << factor;
    }
}

TEST(FloatRange, FarTranslationIsInside) {
    // Positions are taken relative to the camera, so an offset costs float nothing.
    EXPECT_FALSE(floatRangeProblem(translatedScene(test::seedScene(), Vec3(1e10, 1e10, 1e10))));
}

TEST(FloatRange, TooLargeNamesTheSphereAndTheBound) {
    const auto problem = floatRangeProblem(scaledScene(test::seedScene(), 1e15));
    ASSERT_TRUE(problem);
    EXPECT_EQ(*problem,
              "sphere \"floor\" reaches 2e+20 from the camera; float is measured right only up "
              "to 2e+19");
}

TEST(FloatRange, TooSmallNamesTheCheckerAndTheBound) {
    const auto problem = floatRangeProblem(scaledScene(test::seedScene(), 1e-25));
    ASSERT_TRUE(problem);
    EXPECT_EQ(*problem,
              "the checker size of material \"floor\" is 5e-26; float is measured right only "
              "down to 5e-21");
}

TEST(FloatRange, FarLightIsNamed) {
    Scene s = test::seedScene();
    s.lights[0].position = Vec3(0.0, 1e20, 0.0);
    const auto problem = floatRangeProblem(s);
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("light \"key\" lies 1e+20 from the camera"), std::string::npos)
        << *problem;
}

}  // namespace
}  // namespace whitted
