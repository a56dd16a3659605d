// The speed/accuracy trade: error figures with hand-computed values,
// rows that behave as the trade says (more samples, less error; depth past the
// longest chain changes nothing), the truncation map, the Pareto front and the
// progressive curve.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>

#include <nlohmann/json.hpp>

#include "analysis/depth_truncation.h"
#include "analysis/quality_target.h"
#include "analysis/tradeoff.h"
#include "image/image_compare.h"
#include "image/srgb.h"
#include "scene/scene_io.h"
#include "support/core_support.h"
#include "tracer/renderer.h"

namespace whitted {
namespace {

Image uniform(int w, int h, float v) {
    Image image(w, h);
    std::fill(image.rgb.begin(), image.rgb.end(), v);
    return image;
}

TEST(ImageError, IdenticalImages_ZeroErrorInfinitePsnr) {
    const Image a = uniform(4, 3, 0.3f);
    const ErrorStats e = measureError(a, a);
    EXPECT_EQ(e.rmseLinear, 0.0);
    EXPECT_EQ(e.rmseSrgb8, 0.0);
    EXPECT_EQ(e.largest, 0.0);
    EXPECT_TRUE(std::isinf(e.psnrLinear) && e.psnrLinear > 0);
    EXPECT_TRUE(std::isinf(e.psnrSrgb8) && e.psnrSrgb8 > 0);
}

// One convention wherever a PSNR is worked out: no error is +infinity, said
// "∞ dB", and written to JSON as null.
TEST(ImageError, NoErrorAtAll_InfinitePsnrInEveryPlaceThatSaysOne) {
    const QualityPlan plan;         // no depth or precision error measured
    const AdaptiveOutcome reached;  // and none estimated from the samples
    const double db = estimatedPsnr(plan, reached);
    EXPECT_TRUE(std::isinf(db) && db > 0);
    EXPECT_EQ(psnrText(db), "\u221e dB");
    EXPECT_NE(describeReached(plan, reached).find("estimated \u221e dB"), std::string::npos);
    EXPECT_EQ(psnrText(psnrFromMse(255.0 * 255.0 / 1000.0)), "30.0 dB");
    EXPECT_DOUBLE_EQ(psnrFromMse(0.0625, 1.0), 10.0 * std::log10(16.0));
    EXPECT_EQ(nlohmann::json(db).dump(), "null");
}

TEST(ImageError, UniformHalfAgainstQuarter_HandComputed) {
    const ErrorStats e = measureError(uniform(4, 3, 0.5f), uniform(4, 3, 0.25f));
    EXPECT_DOUBLE_EQ(e.rmseLinear, 0.25);
    EXPECT_NEAR(e.psnrLinear, 10.0 * std::log10(1.0 / 0.0625), 1e-12);  // 12.04 dB
    // sRGB codes: 0.5 -> 188, 0.25 -> 137.
    ASSERT_EQ(srgbEncode8(0.5f), 188);
    ASSERT_EQ(srgbEncode8(0.25f), 137);
    EXPECT_DOUBLE_EQ(e.rmseSrgb8, 51.0);
    EXPECT_NEAR(e.psnrSrgb8, 20.0 * std::log10(255.0 / 51.0), 1e-12);  // 13.98 dB
    EXPECT_NEAR(e.largest, (srgbEncode(0.5f) - srgbEncode(0.25f)) * 255.0, 1e-4);
}

TEST(ImageError, SmallerImage_ComparedStretchedOverTheReference) {
    // A 1x1 image of 0.5 against a 2x2 reference with one pixel of 0.5 and three
    // of 0.25: the one pixel is compared with all four.
    Image ref = uniform(2, 2, 0.25f);
    std::fill_n(ref.pixel(1, 1), 3, 0.5f);
    const ErrorStats e = measureError(uniform(1, 1, 0.5f), ref);
    EXPECT_DOUBLE_EQ(e.rmseLinear, std::sqrt(3.0 * 0.0625 / 4.0));
}

// The largest error is the largest displayDifference() of any pixel, exactly,
// though measureError() skips pixels whose codes say they cannot beat it:
// pairs a hair apart across code boundaries, near black (the linear part of
// the curve), and a pixel that is infinite.
TEST(ImageError, Largest_IsTheLargestDisplayDifferenceOfAnyPixel) {
    std::uint32_t state = 12345;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    };
    // Differences of up to a few codes, up to one or two, and mostly under one.
    for (const float spread : {0.02f, 0.004f, 0.0008f}) {
        Image a(64, 48), b(64, 48);
        for (std::size_t i = 0; i < a.rgb.size(); ++i) {
            const float v = i % 7 == 0 ? 0.004f * next() : next();
            a.rgb[i] = v;
            b.rgb[i] = v + (next() - 0.5f) * spread;
        }
        float expected = 0.0f;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 64; ++x)
                expected = std::max(expected, displayDifference(a.pixel(x, y), b.pixel(x, y)));
        EXPECT_DOUBLE_EQ(measureError(a, b).largest, double(expected) * 255.0) << spread;
        a.pixel(40, 30)[1] = std::numeric_limits<float>::infinity();
        EXPECT_DOUBLE_EQ(measureError(a, b).largest, 255.0) << spread;
    }
}

// What the pictures' checks skip std::pow by: the codes' bound is never
// under the exact difference, and never over it by more than the two
// roundings and their slack, on pairs as above; infinite is as far apart
// as can be.
TEST(ImageError, DifferenceAtMost_NeverUnderTheExactOne) {
    std::uint32_t state = 54321;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    };
    int under = 0, tooFar = 0, pairs = 0;
    for (const float spread : {0.02f, 0.004f, 0.0008f})
        for (int i = 0; i < 200000; ++i, ++pairs) {
            float a[3], b[3];
            for (int c = 0; c < 3; ++c) {
                a[c] = i % 7 == 0 ? 0.004f * next() : next();
                b[c] = a[c] + (next() - 0.5f) * spread;
            }
            const float exact = displayDifference(a, b), atMost = displayDifferenceAtMost(a, b);
            under += atMost < exact;
            tooFar += (atMost - exact) * 255.0f > 1.0f + kCodeRoundingSlack;
        }
    EXPECT_EQ(under, 0) << "of " << pairs;
    EXPECT_EQ(tooFar, 0) << "of " << pairs;
    const float a[3] = {0.5f, std::numeric_limits<float>::infinity(), 0.5f}, b[3] = {};
    EXPECT_EQ(displayDifferenceAtMost(a, b), 1.0f);
    EXPECT_EQ(displayDifferenceAtMost(b, b), kCodeRoundingSlack / 255.0f);
}

TEST(Tradeoff, WithSettings_ScalesTheSizeAndSetsTheRest) {
    const Scene s = withSettings(test::seedScene(640, 480), {16, 3, Precision::Double, 0.5});
    EXPECT_EQ(s.render.width, 320);
    EXPECT_EQ(s.render.height, 240);
    EXPECT_EQ(s.render.samplesPerPixel, 16);
    EXPECT_EQ(s.render.maxDepth, 3);
    EXPECT_EQ(s.render.precision, Precision::Double);
    const Scene tiny = withSettings(test::seedScene(3, 2), {1, 1, Precision::Float, 0.01});
    EXPECT_EQ(tiny.render.width, 1);
    EXPECT_EQ(tiny.render.height, 1);
}

TEST(Tradeoff, MoreSamples_LessErrorAgainstTheReference) {
    const Scene scene = test::seedScene(80, 60);
    const ReferenceRender ref = renderReference(scene, 256);
    TradeoffGrid grid;
    grid.samples = {1, 4, 16, 64};
    grid.depths = {ref.scene.render.maxDepth};
    grid.precisions = {Precision::Float};
    grid.scales = {1.0};
    grid.minRuns = grid.maxRuns = 1;
    const std::vector<TradeoffPoint> points = runTradeoff(scene, ref.image, grid);
    ASSERT_EQ(points.size(), 4u);
    for (std::size_t i = 1; i < points.size(); ++i) {
        EXPECT_LT(points[i].error.rmseLinear, points[i - 1].error.rmseLinear) << "row " << i;
        EXPECT_LT(points[i].error.rmseSrgb8, points[i - 1].error.rmseSrgb8) << "row " << i;
        EXPECT_GT(points[i].rays, points[i - 1].rays);
    }
    // 64 samples at the reference's depth is close: under 2 codes RMS.
    EXPECT_LT(points.back().error.rmseSrgb8, 2.0);
}

// One mirror ball over a matt floor: a ray reflected off the ball meets only
// the floor (a sphere never sees itself), so the longest chain is one bounce.
Scene mirrorBallOnMattFloor() {
    Scene s;
    s.camera = Camera{{0, 1, -4}, {0, 0.5, 0}, {0, 1, 0}, 50};
    s.render.width = 48;
    s.render.height = 36;
    s.materials = {
        Material{"mirror", {0.1, 0.1, 0.1}, 0, 50, 0.5, 0, 1.5, std::nullopt},
        Material{"matt", {0.7, 0.7, 0.7}, 0, 50, 0, 0, 1.5, Checker{{0.1, 0.1, 0.1}, 0.5}}};
    s.lights = {Light{"key", {3, 5, -4}, {1, 1, 1}, 1}};
    s.spheres = {Sphere{"ball", {0, 0.5, 0}, 0.5, "mirror"},
                 Sphere{"floor", {0, -1000, 0}, 1000, "matt"}};
    return s;
}

TEST(DepthTruncation, MirrorBall_DepthZeroCutsExactlyKr_DepthOneCutsNothing) {
    Scene s = mirrorBallOnMattFloor();
    s.render.maxDepth = 0;
    const Image cut0 = depthTruncationMap(s);
    EXPECT_EQ(largestTruncation(cut0), 0.5f);  // kr of the ball, on the ball's pixels
    int ballPixels = 0;
    for (float v : cut0.rgb) {
        EXPECT_TRUE(v == 0.0f || v == 0.5f) << v;
        ballPixels += v == 0.5f;
    }
    EXPECT_GT(ballPixels, 30);
    s.render.maxDepth = 1;
    EXPECT_EQ(largestTruncation(depthTruncationMap(s)), 0.0f);
    EXPECT_EQ(depthWithinTolerance(s), 1);
    // Past the longest chain, raising the depth changes nothing at all.
    const Image at1 = test::renderImage(s);
    s.render.maxDepth = 6;
    EXPECT_EQ(test::renderImage(s), at1);
}

TEST(DepthTruncation, Seed_PixelsWithNothingCutOff_DoNotChangeWithOneMoreBounce) {
    Scene s = test::seedScene(96, 72);
    s.render.maxDepth = 2;
    const Image map = depthTruncationMap(s);
    const Image at2 = test::renderImage(s);
    s.render.maxDepth = 3;
    const Image at3 = test::renderImage(s);
    int unchangedChecked = 0, changed = 0;
    for (int y = 0; y < s.render.height; ++y)
        for (int x = 0; x < s.render.width; ++x) {
            const bool same = std::equal(at2.pixel(x, y), at2.pixel(x, y) + 3, at3.pixel(x, y));
            if (map.pixel(x, y)[0] == 0.0f) {
                EXPECT_TRUE(same) << "pixel " << x << "," << y << " changed with nothing cut off";
                ++unchangedChecked;
            } else {
                changed += !same;
            }
        }
    EXPECT_GT(unchangedChecked, 1000);  // the sky
    EXPECT_GT(changed, 100);            // the mirrors and the reflective floor
}

TEST(DepthTruncation, Seed_CutOffShrinksWithDepthBelowToleranceWhereTheSearchStops) {
    Scene s = test::seedScene(96, 72);
    float previous = INFINITY;
    for (int depth : {0, 1, 2, 4}) {
        s.render.maxDepth = depth;
        const float largest = largestTruncation(depthTruncationMap(s));
        EXPECT_LT(largest, previous) << "depth " << depth;
        previous = largest;
    }
    const int enough = depthWithinTolerance(s);
    s.render.maxDepth = enough;
    EXPECT_LT(largestTruncation(depthTruncationMap(s)), 1.0 / 1024.0);
    s.render.maxDepth = enough - 1;
    EXPECT_GE(largestTruncation(depthTruncationMap(s)), 1.0 / 1024.0);
}

// The camera inside a mirror ball: every ray bounces inside it for ever
// with all its weight, so the truncation never settles and the search says
// kMaxDepth. The reference stops at kDeepestChosen (a field of glass balls
// at depth 64 would take days).
TEST(DepthTruncation, Reference_WhereTheTruncationNeverSettles_StopsAtTheDeepestChosen) {
    Scene s = test::seedScene(8, 6);
    Material mirror;
    mirror.name = "perfect mirror";
    mirror.reflectivity = 1.0;
    mirror.diffuse = {0, 0, 0};
    s.materials.push_back(mirror);
    s.spheres = {{"room", {0, 0, 0}, 10.0, "perfect mirror"}};
    s.camera.position = {0, 0, 0};
    s.camera.lookAt = {0, 0, 1};
    ASSERT_EQ(depthWithinTolerance(s), kMaxDepth);
    EXPECT_EQ(renderReference(s, 1).scene.render.maxDepth, kDeepestChosen);
    s.render.maxDepth = 20;  // the scene's own depth is deeper: the reference goes there
    EXPECT_EQ(renderReference(s, 1).scene.render.maxDepth, 20);
}

TEST(DepthTruncation, CancelledReference_EndsPromptly) {
    // scenes/field.json: 2,501 reflective spheres, whose reference at depth 16
    // and 64 samples takes half a minute here, minutes under the sanitizers.
    // A user who cancels Measure waits a row.
    const Scene field = loadScene(WHITTED_SCENES_DIR "/field.json");
    const auto start = std::chrono::steady_clock::now();
    const auto cancelledAfterASecond = [&] {
        return std::chrono::steady_clock::now() - start > std::chrono::seconds(1);
    };
    renderReference(field, 64, cancelledAfterASecond);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 60.0);  // a row takes longer under the sanitizers
}

TEST(Tradeoff, FloatAndDoubleRows_DifferWithinTheNumericsBound) {
    // docs/numerics.md: float and double renders of the seed differ in at most
    // 0.1 % of pixels by more than 2/255, at every setting of the grid.
    const Scene scene = test::seedScene(96, 72);
    for (int depth : {0, 2, 5})
        for (int spp : {1, 4}) {
            const Scene f = withSettings(scene, {spp, depth, Precision::Float, 1.0});
            const Scene d = withSettings(scene, {spp, depth, Precision::Double, 1.0});
            const ImageDifference diff =
                compareImages(test::renderImage(f), test::renderImage(d), 2.0f / 255);
            EXPECT_LE(diff.fractionOver(), 0.001) << "depth " << depth << " spp " << spp;
        }
}

TEST(Tradeoff, ParetoFront_FasterOrMoreAccurateThanEveryOther) {
    auto point = [](double seconds, double rmse) {
        TradeoffPoint p;
        p.seconds = seconds;
        p.error.rmseSrgb8 = rmse;
        return p;
    };
    std::vector<TradeoffPoint> points = {point(1, 10), point(2, 5),    point(2, 8), point(3, 6),
                                         point(4, 1),  point(0.5, 20), point(5, 1)};
    markParetoFront(points);
    const bool expected[] = {true, true, false, false, true, true, false};
    for (std::size_t i = 0; i < points.size(); ++i)
        EXPECT_EQ(points[i].pareto, expected[i]) << "point " << i;
}

TEST(Tradeoff, Stop_ReturnsTheFinishedPointsPromptly) {
    const Scene scene = test::seedScene(40, 30);
    const Image reference = test::renderImage(scene);
    TradeoffGrid grid;
    grid.minRuns = grid.maxRuns = 1;
    int calls = 0;
    const std::vector<TradeoffPoint> points = runTradeoff(
        scene, reference, grid, [&](const TradeoffProgress& p) { calls = p.done; },
        [&] { return calls >= 3; });
    EXPECT_EQ(points.size(), 3u);
}

TEST(Tradeoff, ProgressiveCurve_ErrorFallsPassByPassToTheOneShotRender) {
    Scene scene = test::seedScene(80, 60);
    const ReferenceRender ref = renderReference(scene, 256);
    scene.render.samplesPerPixel = 16;
    scene.render.maxDepth = ref.scene.render.maxDepth;
    const std::vector<ProgressiveSample> curve = progressiveCurve(scene, ref.image);
    ASSERT_EQ(curve.size(), 6u);  // preview, then 1, 2, 4, 8, 16 samples
    EXPECT_EQ(curve.front().samples, 0);
    for (std::size_t i = 1; i < curve.size(); ++i) {
        EXPECT_EQ(curve[i].samples, 1 << (i - 1));
        EXPECT_GE(curve[i].seconds, curve[i - 1].seconds);
        EXPECT_LT(curve[i].error.rmseLinear, curve[i - 1].error.rmseLinear) << "pass " << i;
    }
    // The last pass is the one-shot render, bit for bit, so its error is too.
    const ErrorStats oneShotError = measureError(test::renderImage(scene), ref.image);
    EXPECT_EQ(curve.back().error.rmseLinear, oneShotError.rmseLinear);
}

}  // namespace
}  // namespace whitted
