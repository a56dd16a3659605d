// Whitted's 1980 adaptive sampling (RenderOptions::whitted1980) against the
// paper's procedure written out pixel by pixel here: rays at the corners of the
// pixel, the pixel cut in four where they differ by more than the threshold,
// each quarter likewise down to the limit, a cell the mean of its corners. The
// render must equal it bit for bit whatever its threads and tiles, trace each
// corner once (shared by the pixels and quarters that meet there), and cut
// only where the picture changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <utility>

#include "image/srgb.h"
#include "sphere_field.h"
#include "support/core_support.h"
#include "tracer/renderer.h"

namespace whitted {
namespace {

// The procedure, one pixel at a time, each corner traced where it is needed.
template <typename T>
class PaperSampler {
  public:
    PaperSampler(const Scene& scene, Whitted1980Sampling sampling)
        : s_(prepareScene<T>(scene)), sampling_(sampling), unit_(1 << sampling.maxLevels) {}

    // Pixel (x, y): its value, and how deep it was cut.
    std::pair<Vec<T>, int> pixel(int x, int y) {
        int deepest = 0;
        const Vec<T> value = cell(x * unit_, y * unit_, unit_, 0, deepest);
        return {value, deepest};
    }
    // Every distinct corner traced so far, and how many the cells asked for.
    std::size_t corners() const { return traced_.size(); }
    std::size_t asked() const { return asked_; }

  private:
    Vec<T> corner(long long lx, long long ly) {
        traced_.insert({lx, ly});
        ++asked_;
        RayCounts counts;
        return tracePixelSample(s_, int(lx / unit_), int(ly / unit_), T(lx % unit_) / T(unit_),
                                T(ly % unit_) / T(unit_), counts);
    }

    bool differ(const Vec<T> (&c)[4]) const {
        for (int k = 0; k < 3; ++k) {
            float low = 256, high = -1;
            for (const Vec<T>& v : c) {
                const float code = 255.0f * srgbEncodeFast(float(v[k]));
                low = std::min(low, code);
                high = std::max(high, code);
            }
            if (double(high - low) > sampling_.threshold) return true;
        }
        return false;
    }

    Vec<T> cell(long long x, long long y, long long size, int level, int& deepest) {
        const Vec<T> c[4] = {corner(x, y), corner(x + size, y), corner(x, y + size),
                             corner(x + size, y + size)};
        if (level < sampling_.maxLevels && differ(c)) {
            deepest = std::max(deepest, level + 1);
            const long long h = size / 2;
            return (cell(x, y, h, level + 1, deepest) + cell(x + h, y, h, level + 1, deepest) +
                    cell(x, y + h, h, level + 1, deepest) +
                    cell(x + h, y + h, h, level + 1, deepest)) *
                   T(0.25);
        }
        return (c[0] + c[1] + c[2] + c[3]) * T(0.25);
    }

    PreparedScene<T> s_;
    Whitted1980Sampling sampling_;
    long long unit_;
    std::set<std::pair<long long, long long>> traced_;
    std::size_t asked_ = 0;
};

RenderOptions whitted1980(Whitted1980Sampling sampling, int threads = 2, int tileSize = 32) {
    RenderOptions options = oneShotOptions();
    options.whitted1980 = sampling;
    options.threads = threads;
    options.tileSize = tileSize;
    return options;
}

// The render equals the procedure pixel for pixel, bit for bit, its levels
// too; the procedure's corners: how many distinct, how many asked for.
struct Corners {
    std::size_t distinct = 0, asked = 0;
};

template <typename T>
Corners expectRenderIsThePaper(const Scene& scene, Whitted1980Sampling sampling,
                               const RenderResult& result) {
    PaperSampler<T> paper(scene, sampling);
    int mismatches = 0;
    for (int y = 0; y < scene.render.height; ++y)
        for (int x = 0; x < scene.render.width; ++x) {
            const auto [value, deepest] = paper.pixel(x, y);
            const float* got = result.image.pixel(x, y);
            const bool same = got[0] == float(value.r) && got[1] == float(value.g) &&
                              got[2] == float(value.b) && result.subdivision.at(x, y) == deepest;
            if (!same && mismatches++ < 5)
                ADD_FAILURE() << "pixel " << x << "," << y << ": level "
                              << result.subdivision.at(x, y) << ", the paper's " << deepest;
        }
    EXPECT_EQ(mismatches, 0);
    return {paper.corners(), paper.asked()};
}

TEST(Whitted1980, TheSeed_IsThePapersProcedureBitForBit_InBothPrecisions) {
    const Whitted1980Sampling sampling{8.0, 2};
    for (Precision precision : {Precision::Float, Precision::Double}) {
        const Scene scene = test::seedScene(64, 48, precision);
        const RenderResult result = render(scene, whitted1980(sampling));
        ASSERT_TRUE(result.completed);
        if (precision == Precision::Float)
            expectRenderIsThePaper<float>(scene, sampling, result);
        else
            expectRenderIsThePaper<double>(scene, sampling, result);
    }
}

TEST(Whitted1980, AFieldOfGlassAndMirrors_IsThePapersProcedure_DeeperCuts) {
    FieldOptions field;
    field.count = 60;
    field.seed = 7;
    field.depth = 10;
    const Scene scene = sphereField(field, 48, 36);
    const Whitted1980Sampling sampling{4.0, 3};
    const RenderResult result = render(scene, whitted1980(sampling));
    expectRenderIsThePaper<float>(scene, sampling, result);
    // Some pixels go all the way down, most not at all.
    const auto& levels = result.subdivision.levels;
    EXPECT_GT(std::count(levels.begin(), levels.end(), 3), 0);
    EXPECT_GT(std::count(levels.begin(), levels.end(), 0), int(levels.size()) / 3);
}

TEST(Whitted1980, AnyThreadsAndTiles_TheSamePicture) {
    const Scene scene = test::seedScene(50, 37);
    const Whitted1980Sampling sampling{6.0, 2};
    const RenderResult one = render(scene, whitted1980(sampling, 1, 64));
    for (const auto& [threads, tile] : {std::pair{2, 7}, {3, 16}, {2, 1}}) {
        const RenderResult other = render(scene, whitted1980(sampling, threads, tile));
        EXPECT_TRUE(test::samePixels(other.image, one.image))
            << threads << " threads, tile " << tile << ": "
            << test::firstDifference(other.image, one.image);
        EXPECT_EQ(other.subdivision.levels, one.subdivision.levels);
    }
}

TEST(Whitted1980, OneTile_TracesEachCornerOnce) {
    const Scene scene = test::seedScene(40, 30);
    const Whitted1980Sampling sampling{8.0, 2};
    const RenderResult result = render(scene, whitted1980(sampling, 1, 64));
    const Corners corners = expectRenderIsThePaper<float>(scene, sampling, result);
    EXPECT_EQ(result.rays.camera, corners.distinct);
    // Each corner serves up to four cells: shared, a third of the rays or fewer.
    EXPECT_LT(result.rays.camera * 3, corners.asked);
    EXPECT_GT(result.rays.camera, std::uint64_t(41 * 31));
}

TEST(Whitted1980, AnEvenSky_IsItsCornersAlone) {
    Scene scene = test::seedScene(20, 10);
    scene.spheres.clear();
    scene.background = Vec3(0.2, 0.4, 0.6);
    const RenderResult result = render(scene, whitted1980({0.0, 4}));
    EXPECT_EQ(result.rays.camera, std::uint64_t(21 * 11));
    EXPECT_TRUE(std::all_of(result.subdivision.levels.begin(), result.subdivision.levels.end(),
                            [](std::uint8_t level) { return level == 0; }));
    EXPECT_EQ(result.image.pixel(7, 3)[1], 0.4f);
}

TEST(Whitted1980, NoCutsAllowed_EachPixelTheMeanOfItsCorners) {
    const Scene scene = test::seedScene(32, 24);
    const RenderResult result = render(scene, whitted1980({8.0, 0}));
    EXPECT_EQ(result.rays.camera, std::uint64_t(33 * 25));
    expectRenderIsThePaper<float>(scene, {8.0, 0}, result);
    // A threshold no corners can pass: the same picture with cuts allowed.
    const RenderResult never = render(scene, whitted1980({255.0, 3}));
    EXPECT_TRUE(test::samePixels(never.image, result.image))
        << test::firstDifference(never.image, result.image);
}

TEST(Whitted1980, TheBallsEdges_AreCut_TheFloorsMiddleIsNot) {
    const Scene scene = test::seedScene(64, 48);
    const RenderResult result = render(scene, whitted1980({8.0, 2}));
    // The sky at the top is even; the blue ball's outline is not.
    for (int x = 0; x < 64; ++x) EXPECT_EQ(result.subdivision.at(x, 0), 0) << x;
    const PixelRect ball = {40, 20, 12, 12};
    int cut = 0;
    for (int y = ball.y; y < ball.y + ball.height; ++y)
        for (int x = ball.x; x < ball.x + ball.width; ++x) cut += result.subdivision.at(x, y) > 0;
    EXPECT_GT(cut, 5);
}

TEST(Whitted1980, WithATargetRegionsOrTooDeep_Refused) {
    const Scene scene = test::seedScene(16, 12);
    RenderOptions options = whitted1980({8.0, 2});
    options.adaptive = AdaptiveSampling{};
    EXPECT_THROW(render(scene, options), std::invalid_argument);
    options = whitted1980({8.0, 2});
    options.regions = {{0, 0, 8, 8}};
    EXPECT_THROW(render(scene, options), std::invalid_argument);
    EXPECT_THROW(render(scene, whitted1980({8.0, kMaxWhitted1980Levels + 1})),
                 std::invalid_argument);
    EXPECT_THROW(render(scene, whitted1980({-1.0, 2})), std::invalid_argument);
}

TEST(Whitted1980, Stopped_SaysSoAndKeepsNoSamples) {
    const Scene scene = test::seedScene(64, 48);
    const RenderResult result = render(scene, whitted1980({8.0, 2}), {}, [] { return true; });
    EXPECT_FALSE(result.completed);
    EXPECT_EQ(result.samples, 0);
}

}  // namespace
}  // namespace whitted
