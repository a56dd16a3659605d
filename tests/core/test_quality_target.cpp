// Rendering to a quality (core/analysis/quality_target.h), checked
// where the presets were never fitted: random fields of matte, mirror and
// glass balls (app/field), each against a converged reference (double, 512
// samples a pixel, depth 14). The targets must be met in at least 95% of the
// twelve renders, which is all of them, and Final with no more rays than the
// fixed sample count that would meet it at the same depth (rays, not seconds:
// a count does not depend on the machine's load). Draft and Preview do not
// get there at this size: Draft starts with the pixels' centres, but at
// 128x96, where balls are a few pixels wide, their estimate sends most tiles
// on to two samples; Preview's planning and first two samples cost more than
// the fixed samples it needs. Their ratios are printed, and docs/design/quality-planning.md
// has them at 320x240.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/depth_truncation.h"
#include "analysis/quality_check.h"
#include "image/image_error.h"
#include "image/image_parts.h"
#include "scene/scene_io.h"
#include "support/quality_fields.h"
#include "tracer/renderer.h"

namespace whitted {
namespace {

QualityTarget preset(const std::string& name) {
    if (name == "Draft") return draftQuality();
    if (name == "Preview") return previewQuality();
    return finalQuality();
}

// One field (tests/support/quality_fields.h) and preset a test case, so that
// they run side by side; each must meet its target, as 95% of the twelve
// renders did when they ran as one.
struct FieldAndPreset {
    std::uint32_t seed;
    std::string preset;
    // Final on the two smaller fields has a fixed sample count that meets it
    // (on the two larger none does today): the rays are compared there at least.
    bool hasAFixedCountToBeat = false;
};

class PresetOnAField : public testing::TestWithParam<FieldAndPreset> {};

TEST_P(PresetOnAField, MeetsItsTargetOnAFieldItWasNotFittedOn) {
    const Scene scene = test::qualityField(GetParam().seed);
    const QualityTarget target = preset(GetParam().preset);
    const Image reference = test::qualityFieldReference(GetParam().seed);
    const QualityCheck c = checkQuality(scene, target, reference);
    const FixedCheck fixed = fewestFixedSamplesMeeting(scene, target, c.plan.maxDepth, reference);
    std::printf(
        "%zu balls, %-8s depth %2d: %5.1f dB (estimated %5.1f), largest %5.1f "
        "codes, %s; rays %.2fM against %.2fM at %d fixed samples\n",
        scene.spheres.size() - 1, target.name.c_str(), c.plan.maxDepth, c.error.psnrSrgb8,
        c.estimatedPsnr, c.error.largest, c.met ? "met" : "MISSED", c.rays / 1e6, fixed.rays / 1e6,
        fixed.samples);
    EXPECT_TRUE(c.met);
    if (target.name != "Final") return;
    if (GetParam().hasAFixedCountToBeat) {
        EXPECT_GT(fixed.samples, 0);
    }
    if (fixed.samples > 0) {
        EXPECT_LE(c.rays, fixed.rays)
            << "Final took more rays than " << fixed.samples << " fixed samples";
    }
}

INSTANTIATE_TEST_SUITE_P(QualityTarget, PresetOnAField,
                         testing::Values(FieldAndPreset{1, "Draft"}, FieldAndPreset{1, "Preview"},
                                         FieldAndPreset{1, "Final", true},
                                         FieldAndPreset{2, "Draft"}, FieldAndPreset{2, "Preview"},
                                         FieldAndPreset{2, "Final", true},
                                         FieldAndPreset{3, "Draft"}, FieldAndPreset{3, "Preview"},
                                         FieldAndPreset{3, "Final"}, FieldAndPreset{4, "Draft"},
                                         FieldAndPreset{4, "Preview"}, FieldAndPreset{4, "Final"}),
                         [](const testing::TestParamInfo<FieldAndPreset>& info) {
                             return "Field" + std::to_string(info.param.seed) + "_" +
                                    info.param.preset;
                         });

// A shipped scene at 320x240, in float.
Scene shippedSceneInFloat(const std::string& file) {
    Scene scene = loadScene(WHITTED_SCENES_DIR "/" + file);
    scene.render.width = 320;
    scene.render.height = 240;
    scene.render.precision = Precision::Float;
    return scene;
}

// Float against double at the probe's size, depth and samples: the mean
// squared difference of their 8-bit pictures.
double floatAgainstDouble(Scene scene, int samples) {
    scene.render.samplesPerPixel = samples;
    scene.render.precision = Precision::Float;
    const Image inFloat = render(scene, oneShotOptions()).image;
    scene.render.precision = Precision::Double;
    const ErrorStats e = measureError(inFloat, render(scene, oneShotOptions()).image);
    return e.rmseSrgb8 * e.rmseSrgb8;
}

// On glass.json float and double part at pixels' centres in slivers of the
// balls' rims: 0.4 codes^2 against Final's 0.65 at one sample a pixel, under
// a hundredth of that at 256. The plan measures it again with 8 samples a
// pixel and counts what it finds there, no less than what 256 samples show.
TEST(QualityTarget, FloatAgainstDouble_MeasuredWithSamplesWhereTheCentresDifferMuch) {
    Scene glass = shippedSceneInFloat("glass.json");
    const QualityPlan plan = planQuality(glass, finalQuality());
    EXPECT_EQ(plan.precisionSamples, 8);
    EXPECT_NE(plan.why.find("float against double: "), std::string::npos);
    EXPECT_NE(plan.why.find(", at 8 samples a pixel"), std::string::npos) << plan.why;
    Scene probe = glass;
    probe.render.width = plan.probeWidth;
    probe.render.height = plan.probeHeight;
    probe.render.maxDepth = plan.maxDepth;
    const double atCentres = floatAgainstDouble(probe, 1);
    const double atMany = floatAgainstDouble(probe, 256);
    std::printf("float against double: centres %.4f, planned %.4f, 256 samples %.4f codes^2\n",
                atCentres, plan.precisionMse, atMany);
    EXPECT_LT(plan.precisionMse, atCentres / 4.0);
    EXPECT_GE(plan.precisionMse, atMany);
    // A render of one sample a pixel at most shows the centres' difference:
    // that is what its plan counts.
    const QualityPlan oneSample = planQuality(glass, finalQuality(), 1);
    EXPECT_EQ(oneSample.precisionSamples, 1);
    EXPECT_NEAR(oneSample.precisionMse, atCentres, 1e-9);
    // Where the centres' difference is small, it is what the plan counts.
    Scene seed = loadScene(WHITTED_SCENES_DIR "/seed.json");
    seed.render.precision = Precision::Float;
    EXPECT_EQ(planQuality(seed, finalQuality()).precisionSamples, 1);
}

// The largest difference between `scene` at `depth` and three levels deeper,
// with `samples` a pixel in the scene's precision, in codes.
double largestDepthDifference(Scene scene, int depth, int samples) {
    scene.render.samplesPerPixel = samples;
    scene.render.maxDepth = depth;
    const Image shallow = render(scene, oneShotOptions()).image;
    scene.render.maxDepth = depth + 3;
    return measureError(shallow, render(scene, oneShotOptions()).image).largest;
}

// On seed.json at Final the picture's pixel centres at depth 4 differ from
// depth 7 by more than the depth's share of the largest error (a reflection's
// edge, in a sliver of a pixel: 21 codes, 8 allowed); a render of many
// samples shares that out over the pixel. The plan renders those pixels
// again with 8 samples each and takes a depth that 256 samples a pixel bear
// out, shallower than the centres alone would take.
TEST(QualityTarget, DepthLargestError_JudgedWithSamplesWhereTheCentresShowASliver) {
    Scene seed = shippedSceneInFloat("seed.json");
    const QualityPlan plan = planQuality(seed, finalQuality());
    EXPECT_TRUE(plan.depthAtPictureSize);
    EXPECT_EQ(plan.depthLargestSamples, 8);
    EXPECT_NE(plan.why.find("with 8 samples a pixel of the picture where the centres differ"),
              std::string::npos)
        << plan.why;
    // A plan for one sample a pixel judges by the centres, which that render shows.
    const QualityPlan centresOnly = planQuality(seed, finalQuality(), 1);
    EXPECT_EQ(centresOnly.depthLargestSamples, 1);
    EXPECT_GT(centresOnly.maxDepth, plan.maxDepth);
    const double share = kPictureShareOfLargest * *finalQuality().largestCodes;
    const double atCentres = largestDepthDifference(seed, plan.maxDepth, 1);
    const double atMany = largestDepthDifference(seed, plan.maxDepth, 256);
    std::printf("depth %d against %d: centres %.1f, planned %.1f, 256 samples %.1f codes\n",
                plan.maxDepth, plan.maxDepth + 3, atCentres, plan.depthLargest, atMany);
    EXPECT_GT(atCentres, share);
    EXPECT_LE(plan.depthLargest, share);
    EXPECT_LE(atMany, share);
    EXPECT_TRUE(checkQuality(seed, finalQuality(), convergedReference(seed)).met);
}

// A field of 114 balls at 160x120 (bench_quality_fields' second) where light
// trapped in a small glass ball makes a streak a pixel wide 94 codes
// brighter from depth 5 to 8, between the centres of the depth's 40x30
// probe: with the probe alone the plan took depth 5, and Preview's render had
// a pixel 96.9 codes off (64 allowed). Checked at the picture's own size, the
// depth the plan takes leaves no pixel of the picture more than half the
// limit short of three levels deeper.
TEST(QualityTarget, DepthCheckedAtThePicturesSize_SeesWhatFallsBetweenTheProbesCentres) {
    const Scene field =
        sphereField({.count = 114, .seed = 502, .halfWidth = 4.0, .depth = 8.0}, 160, 120);
    const double limit = *previewQuality().largestCodes;
    const QualityPlan plan = planQuality(field, previewQuality());
    EXPECT_TRUE(plan.depthAtPictureSize);
    EXPECT_LT(plan.probeWidth, field.render.width);
    const double atDepth5 = largestDepthDifference(field, 5, 64);
    const double planned = largestDepthDifference(field, plan.maxDepth, 64);
    std::printf("depth 5 against 8: %.1f codes; depth %d against %d: %.1f codes (64 samples)\n",
                atDepth5, plan.maxDepth, plan.maxDepth + 3, planned);
    EXPECT_GT(atDepth5, limit);
    EXPECT_LE(planned, limit / 2);
}

// What lets a check that goes on past a depth look again only at the pixels
// it left in doubt: each level deeper adds light and takes none away, in
// every channel of every pixel, pruned as plans render, but for rounding
// (the deepest picture is the tracer's own sum of a path, the shallower
// ones its levels summed: they part in the last bit). A field of glass and
// mirror balls, its centres and two samples a pixel, depths 3 to 16.
TEST(QualityTarget, EachLevelDeeperAddsLight_NoPixelDarker) {
    Scene field =
        sphereField({.count = 114, .seed = 502, .halfWidth = 4.0, .depth = 8.0}, 160, 120);
    field.render.maxDepth = 16;
    RenderOptions options = oneShotOptions();
    options.pruneBelowWeight = kQualityPruneWeight;
    for (int depth = 3; depth < 16; ++depth) options.alsoAtDepths.push_back(depth);
    for (int samples : {1, 2}) {
        field.render.samplesPerPixel = samples;
        RenderResult r = render(field, options);
        r.atDepths.push_back(std::move(r.image));
        int darker = 0, brighter = 0;
        for (std::size_t k = 1; k < r.atDepths.size(); ++k)
            for (std::size_t i = 0; i < r.atDepths[k].rgb.size(); ++i) {
                const float before = r.atDepths[k - 1].rgb[i], after = r.atDepths[k].rgb[i];
                darker += after < before * (1.0f - 1e-6f);
                brighter += after > before * (1.0f + 1e-6f);
            }
        EXPECT_EQ(darker, 0) << samples << " samples a pixel";
        EXPECT_GT(brighter, 1000) << samples << " samples a pixel";  // light trapped in glass
    }
}

// mirrors.json's Preview at the 640x480 it is saved at: the check at the
// picture's size goes on from the probe's depth 6, 47.5 codes off depth 16
// at 8 samples a pixel, to 7, 32.5 codes (32 allowed), to 8. Past the first
// depth it renders only the pixels the depth before left in doubt, not the
// whole picture again: its rays are under one and a half renders of the
// picture's centres. Its verdict is the whole picture's: depth 7 with 8
// samples everywhere is over the share, depth 8 within what the plan says
// (14.3 codes against 28.4, depth 6's figure for the pixels not in doubt;
// when the check rendered the whole picture again it said 9.9, for the
// centres of those pixels).
TEST(QualityTarget, CheckGoingOn_RendersOnlyThePixelsInDoubt) {
    Scene mirrors = loadScene(WHITTED_SCENES_DIR "/mirrors.json");
    ASSERT_EQ(mirrors.render.width, 640);
    const QualityPlan plan = planQuality(mirrors, previewQuality());
    EXPECT_EQ(plan.maxDepth, 8) << plan.why;
    EXPECT_TRUE(plan.depthAtPictureSize);
    EXPECT_FALSE(plan.depthShort);
    Scene centres = mirrors;
    centres.render.samplesPerPixel = 1;
    centres.render.maxDepth = plan.referenceDepth;
    RenderOptions pruned = oneShotOptions();
    pruned.pruneBelowWeight = kQualityPruneWeight;
    const std::uint64_t pictureRays = render(centres, pruned).rays.total();
    std::printf("planning traced %.2fM rays, one render of the centres %.2fM\n",
                plan.probeRays / 1e6, pictureRays / 1e6);
    EXPECT_LT(double(plan.probeRays), 1.5 * double(pictureRays));
    auto largestAt = [&](int depth) {
        Scene s = mirrors;
        s.render.samplesPerPixel = 8;
        s.render.maxDepth = depth;
        const Image shallow = render(s, pruned).image;
        s.render.maxDepth = plan.referenceDepth;
        return measureError(shallow, render(s, pruned).image).largest;
    };
    const double share = kPictureShareOfLargest * *previewQuality().largestCodes;
    EXPECT_GT(largestAt(plan.maxDepth - 1), share);
    const double atPlanned = largestAt(plan.maxDepth);
    std::printf("depth %d with 8 samples a pixel: %.1f codes, the plan says %.1f at most\n",
                plan.maxDepth, atPlanned, plan.depthLargest);
    EXPECT_LE(atPlanned, plan.depthLargest);
}

// The largest error in `region` of a render of the whole of bench_quality_fields'
// first field, at the 640x480 it is saved at, to `target`'s plan, against
// 512 samples a pixel at the plan's own depth (what the samples leave).
struct RegionError {
    double largest = 0.0;  // codes
    int depth = 0;
};

// The largest error in `region` of bench_quality_fields' field `seed` at
// 640x480 rendered to `target`, against 512 samples a pixel: at
// `referenceDepth` in double, pruned as convergedReference() prunes; where
// none is given, at the plan's own depth and precision, so that only the
// sampling's error counts.
RegionError fieldErrorIn(int seed, const QualityTarget& target, const PixelRect& region,
                         std::optional<int> referenceDepth = {}) {
    const Scene field = sphereField(untunedField(seed));
    EXPECT_EQ(field.render.width, 640);
    const QualityPlan plan = planQuality(field, target);
    Scene planned = field;
    RenderOptions options = oneShotOptions();
    applyPlan(plan, planned, options);
    const Image ours = render(planned, options).image;
    Image reference;
    if (referenceDepth) {
        reference = convergedReference(planned, 512, *referenceDepth, {region});
    } else {
        Scene converged = planned;
        converged.render.samplesPerPixel = 512;
        RenderOptions fixed = oneShotOptions();
        fixed.regions = {region};
        reference = render(converged, fixed).image;
    }
    return {measureError(cropImage(ours, region), cropImage(reference, region)).largest,
            plan.maxDepth};
}

// A checker reflected in a small magenta ball, where a single draw per
// pixel of the sampling's estimate let pixels stop 65 to 70 codes off (64
// allowed) while their estimates stayed under 0.8 of the limit; at 160x120
// the tiles are sampled well past that, and none was. The plan's depth cuts
// off nothing there.
TEST(QualityTarget, PreviewAtTheSizeAFieldIsSavedAt_NoPixelOfAReflectedCheckerOverTheLimit) {
    const RegionError e = fieldErrorIn(1, previewQuality(), {48, 224, 96, 64});
    EXPECT_LE(e.largest, *previewQuality().largestCodes) << "depth " << e.depth;
}

// The same field's Final: its pixel (434, 402) is black but for a corner of
// a bright ball's edge, about a fiftieth of it, which none of its first 32
// samples hit. The halves agreed, its tile stopped there, and the pixel
// was 18.2 codes off (16 allowed). Taken also as off by one more sample of
// its neighbours' colour (unseenLargest()), the tile goes on.
TEST(QualityTarget, FinalAtTheSizeAFieldIsSavedAt_APixelWhoseSamplesMissedASliver) {
    const RegionError e = fieldErrorIn(1, finalQuality(), {426, 394, 16, 16});
    EXPECT_LE(e.largest, *finalQuality().largestCodes) << "depth " << e.depth;
}

// bench_quality_fields' fifth field at 640x480: light trapped in a small
// glass ball comes out in a curve a pixel or two long. At depth 36 it
// passes through the centre of pixel (198, 302), 161 codes short of depth
// 64 there, but 8 samples showed 31 codes of that pixel (32 allowed at the
// picture's check), and its neighbour (199, 303), whose centre the curve
// misses, was not looked at: the Preview took depth 36 and that pixel was
// 68 codes off (64 allowed). Judged with samples around a pixel in doubt
// too, the plan goes deeper.
TEST(QualityTarget, PreviewAtTheSizeAFieldIsSavedAt_LightBesideACentreThatSawIt) {
    const RegionError e =
        fieldErrorIn(5, previewQuality(), {193, 297, 13, 13}, kDeepReferenceDepth);
    std::printf("depth %d: %.1f codes\n", e.depth, e.largest);
    EXPECT_GT(e.depth, 36);
    EXPECT_LE(e.largest, *previewQuality().largestCodes);
}

// bench_quality_fields' field `seed` at `width` x `height`.
Scene untunedFieldAt(int seed, int width, int height) {
    Scene field = sphereField(untunedField(seed));
    field.render.width = width;
    field.render.height = height;
    return field;
}

// `field` rendered to Final and judged against a reference as deep as the
// plan's check looks (kDeepReferenceDepth); the plan's reasons printed.
QualityCheck finalAgainstDeepReference(const Scene& field) {
    const QualityCheck c =
        checkQuality(field, finalQuality(), convergedReference(field, 512, kDeepReferenceDepth));
    std::printf("depth %d: %.1f dB, %.1f codes\n%s\n", c.plan.maxDepth, c.error.psnrSrgb8,
                c.error.largest, c.plan.why.c_str());
    return c;
}

// bench_quality_fields' tenth field at 160x120: light trapped in a glass
// ball comes out in a sliver of one pixel, between its centre and its eight
// neighbours' (depth 10 against 16 at those nine centres: nothing; with 8
// samples a pixel, 16.5 codes). Checked at the centres alone, Final took
// depth 10 and the render was 20.2 codes off a depth-19 reference at that
// pixel (16 allowed). With two samples a pixel besides the centres the plan
// sees the sliver, goes deeper, and the render meets its target.
TEST(QualityTarget, PictureCheckedWithSamples_SeesASliverBetweenTheCentres) {
    const QualityCheck c = finalAgainstDeepReference(untunedFieldAt(10, 160, 120));
    EXPECT_GT(c.plan.maxDepth, 10);
    EXPECT_NE(c.plan.why.find("at the centres or with 2 samples a pixel"), std::string::npos);
    EXPECT_TRUE(c.met);
}

// A render to a quality follows no ray that passes on less than
// kQualityPruneWeight of the light. bench_quality_fields' thirteenth field
// takes Final past depth 16, where the light trapped in its glass balls is
// followed to the end and their faint inner reflections are not. Followed
// whole, such a render doubles its rays with each level past 16 (at the
// plan's depth it never finished); at depth 16, with the plan's samples (16
// a pixel at most), the pruned render traces under half the rays of the one
// traced whole, and no pixel is a code apart.
TEST(QualityTarget, RenderToAPlan_FollowsOnlyTheRaysThatStillMatter) {
    const Scene field = untunedFieldAt(13, 160, 120);
    const QualityPlan plan = planQuality(field, finalQuality(), 16);
    Scene planned = field;
    RenderOptions options = oneShotOptions();
    applyPlan(plan, planned, options);
    EXPECT_EQ(options.pruneBelowWeight, kQualityPruneWeight);
    EXPECT_GT(planned.render.maxDepth, kDeepestChosen) << plan.why;
    EXPECT_NE(plan.why.find("following no ray that passes on less than 0.0001 of the light"),
              std::string::npos)
        << plan.why;
    planned.render.maxDepth = kDeepestChosen;
    const RenderResult pruned = render(planned, options);
    options.pruneBelowWeight = 0.0;
    const RenderResult whole = render(planned, options);
    const double share = double(pruned.rays.total()) / double(whole.rays.total());
    const double largest = measureError(pruned.image, whole.image).largest;
    std::printf("planned depth %d; at %d: %.2f of the rays, largest difference %.2f codes\n",
                plan.maxDepth, kDeepestChosen, share, largest);
    EXPECT_LT(share, 0.5);
    EXPECT_GT(largest, 0.0);  // something was pruned
    EXPECT_LE(largest, 1.0);
}

// bench_quality_fields' nineteenth field: light trapped among its glass balls
// still changes pixels past depth 16 (at 160x120 one by 98 codes from depth
// 16 to 64). While plans stopped at 16, its Final said so ("the target may
// be missed") and was 30 codes off a depth-19 reference where 16 are
// allowed, a reference itself short of the light. Now the plan is checked at
// the picture's size against the deepest depth SPEC allows, goes on past 16
// to a depth that fits there, and the render meets Final against a
// reference of that depth (at 80x60, where the reference takes a quarter of
// the time).
TEST(QualityTarget, LightTrappedPastDepth16_PlannedAsDeepAsItGoes) {
    const QualityCheck c = finalAgainstDeepReference(untunedFieldAt(19, 80, 60));
    EXPECT_GT(c.plan.maxDepth, kDeepestChosen);
    EXPECT_TRUE(c.plan.depthAtPictureSize);
    EXPECT_FALSE(c.plan.depthShort);
    EXPECT_TRUE(c.met);
}

// A room of lossless mirrors, the camera and a ball inside it: light goes
// round it for ever, and a ray that reaches the ball only after sixty
// bounces changes its pixel from black to the ball's colour. `bright`: a
// white ball under a light twice as strong.
Scene mirrorRoom(int width, int height, bool bright) {
    Scene room;
    room.camera = {{0, 0, -3}, {0, 0, 5}, {0, 1, 0}, 60.0};
    room.render.width = width;
    room.render.height = height;
    Material mirror, paint;
    mirror.name = "lossless mirror";
    mirror.diffuse = {0, 0, 0};
    mirror.reflectivity = 1.0;
    paint.name = "paint";
    paint.diffuse = bright ? Vec3{0.9, 0.9, 0.9} : Vec3{0.7, 0.08, 0.06};
    paint.specular = 0.5;
    paint.shininess = 60;
    room.materials = {mirror, paint};
    room.lights = {{.name = "key", .position = {3, 4, -2}, .intensity = bright ? 2.0 : 1.0}};
    room.spheres = {{"room", {0, 0, 0}, 10.0, "lossless mirror"},
                    {"ball", {4, -3, 4}, 1.0, "paint"}};
    return room;
}

// In a room of lossless mirrors no depth the plan may choose fits Final's
// share: it takes the deepest, kLookAhead short of the 64 SPEC allows, and
// says what is short. Where what that depth cuts off is over the whole limit
// of 16 codes, samples cannot take it back, and the plan says a pixel is
// likely to be off by more: the picture with 8 samples a pixel bears it out.
// Where it is under the limit the plan only says the target may be missed.
TEST(QualityTarget, DepthShortOverTheLimit_SaysAPixelIsLikelyToBeOffByMore) {
    const Scene bright = mirrorRoom(80, 60, true);
    const QualityPlan plan = planQuality(bright, finalQuality());
    const double limit = *finalQuality().largestCodes;
    EXPECT_TRUE(plan.depthShort);
    EXPECT_EQ(plan.maxDepth, kMaxDepth - 3);
    EXPECT_GT(plan.depthLargest, limit);
    EXPECT_NE(plan.why.find("no depth up to 61 leaves the samples their share"), std::string::npos)
        << plan.why;
    EXPECT_NE(plan.why.find("so a pixel is likely to be off by more than 16 codes"),
              std::string::npos)
        << plan.why;
    const double cut = largestDepthDifference(bright, plan.maxDepth, 8);
    std::printf("depth %d against %d: planned %.1f, 8 samples %.1f codes\n", plan.maxDepth,
                plan.maxDepth + 3, plan.depthLargest, cut);
    EXPECT_GT(cut, limit);

    // What the deepest depth cuts off is more than Final's whole MSE, and
    // the plan names the depth for what it is: chosen, not given.
    EXPECT_GT(plan.depthMse, allowedMse(finalQuality().psnrDb));
    EXPECT_NE(plan.why.find("the deepest depth planned alone cuts off more than the "
                            "target allows: it cannot be met"),
              std::string::npos)
        << plan.why;
    // Its samples are not sent after the rest of a budget the depth has spent
    // (at 0.052 codes^2 a dense glass field took 602 samples a pixel): they
    // aim for the noise they would have at a depth that fits, and the plan
    // says so.
    const double total = allowedMse(finalQuality().psnrDb);
    EXPECT_GE(plan.sampling.allowedMse, kSamplingShare * (1 - kDepthShareOfMse) * total);
    EXPECT_NE(plan.why.find("so the samples aim for the noise of a picture that meets it"),
              std::string::npos)
        << plan.why;

    const QualityPlan underLimit = planQuality(mirrorRoom(80, 60, false), finalQuality());
    EXPECT_TRUE(underLimit.depthShort);
    EXPECT_LE(underLimit.depthLargest, limit);
    EXPECT_NE(underLimit.why.find("so the target may be missed"), std::string::npos)
        << underLimit.why;
}

}  // namespace
}  // namespace whitted
