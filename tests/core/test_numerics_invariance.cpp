// Numerics tests: the seed scene must look the same however it is
// scaled or moved, and float must agree with double on it.
//
// Every comparison uses compareImages() (core/image/image_compare.h): per pixel the
// largest channel difference after the sRGB curve, so "within 1/255" means one
// step of an 8-bit display value. The thresholds:
//  - scaled by 2^k, k in [-20, 20]: bit-identical (exact scaling; any difference
//    exposes an absolute epsilon or a scale-dependent branch);
//  - scaled by 10^k: >= 99.9 % of pixels within 1/255 (float, k in [-4, 4]),
//    >= 99.99 % (double, k in [-8, 8]);
//  - moved by 10^k (1,1,1) (whole multiples of twice the checker size 0.5, so the
//    checker moves with the scene): the same 99.9 % / 99.99 % within 1/255, for
//    float k = 2 .. 5 and double k = 2 .. 9;
//  - float against double: at most 0.1 % of pixels differ by more than 2/255, and
//    no pixel is in shadow in float where it is lit in double: the primary ray
//    through each pixel centre is traced in both precisions; where both hit the
//    same sphere, each light with N.L > 0 in both (the only place the tracer
//    traces a shadow ray) gets S in both, and S < 1 in float with S == 1 in
//    double counts as falsely shadowed.
// Images that fail are written, with a difference map, to
// $TMPDIR/whitted-numerics/ (the path is printed).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "camera/view_projection.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "scene/scene_transform.h"
#include "support/numerics_support.h"

namespace whitted {
namespace {

constexpr int kWidth = 200, kHeight = 150;  // 30000 pixels: 0.01 % is 3 pixels
constexpr float kDisplayStep = 1.0f / 255.0f;

// Writes both images and a map of their differences (grey: difference up to the
// threshold, red: over it) for a failed comparison; returns where.
std::string writeFailure(const Image& expected, const Image& actual, float threshold,
                         const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "whitted-numerics";
    std::filesystem::create_directories(dir);
    Image diff(expected.width, expected.height);
    for (std::size_t i = 0; i < std::size_t(expected.width) * expected.height; ++i) {
        const float d = displayDifference(&expected.rgb[3 * i], &actual.rgb[3 * i]);
        const float grey = std::min(1.0f, d / threshold);
        diff.rgb[3 * i] = d > threshold ? 1.0f : grey;
        diff.rgb[3 * i + 1] = d > threshold ? 0.0f : grey;
        diff.rgb[3 * i + 2] = d > threshold ? 0.0f : grey;
    }
    try {
        const ImageMetadata meta;
        writeImage(expected, dir / (name + "-expected.png"), meta);
        writeImage(actual, dir / (name + "-actual.png"), meta);
        writeImage(diff, dir / (name + "-diff.png"), meta);
    } catch (const std::exception& e) {
        return std::string("(could not write images: ") + e.what() + ")";
    }
    return (dir / (name + "-{expected,actual,diff}.png")).string();
}

std::string percent(double fraction) {
    std::ostringstream s;
    s << std::setprecision(6) << 100.0 * fraction << " %";
    return s.str();
}

// ---- scale ----------------------------------------------------------------------

void checkPowerOfTwoScaling(Precision precision) {
    const Scene seed = test::seedScene(160, 120, precision);
    const Image base = test::renderImage(seed);
    std::string failures;
    for (int k = -20; k <= 20; ++k) {
        if (k == 0) continue;
        const Image scaled = test::renderImage(scaledScene(seed, std::ldexp(1.0, k)));
        if (scaled.rgb == base.rgb) continue;
        const ImageDifference d = compareImages(base, scaled, 0.0f);
        std::ostringstream o;
        o << "\n  2^" << k << ": " << d.over << " of " << d.pixels
          << " pixels differ, largest display difference " << d.largest * 255 << "/255, "
          << compareImages(base, scaled, kDisplayStep).over << " by more than 1/255; "
          << writeFailure(base, scaled, kDisplayStep,
                          "scale-2^" + std::to_string(k) + "-" + test::label(precision));
        failures += o.str();
    }
    std::cout << "[ MEASURED ] " << test::label(precision) << " 2^k scaling, k in [-20, 20]: "
              << (failures.empty() ? "all bit-identical" : failures) << std::endl;
    EXPECT_TRUE(failures.empty()) << "not bit-identical:" << failures;
}

TEST(NumericsInvariance, ScaleByPowerOfTwoFloat_SeedScene_BitIdentical) {
    checkPowerOfTwoScaling(Precision::Float);
}

TEST(NumericsInvariance, ScaleByPowerOfTwoDouble_SeedScene_BitIdentical) {
    checkPowerOfTwoScaling(Precision::Double);
}

// Renders `moved(seed, k)` for k in [kLo, kHi] and requires at least `share` of
// the pixels within 1/255 of the seed itself in the same precision.
template <typename Transform>
void checkNearlyInvariant(Precision precision, int kLo, int kHi, double share, const char* what,
                          Transform moved) {
    const Scene seed = test::seedScene(kWidth, kHeight, precision);
    const Image base = test::renderImage(seed);
    std::ostringstream table, failures;
    for (int k = kLo; k <= kHi; ++k) {
        if (k == 0) continue;
        const Image image = test::renderImage(moved(seed, k));
        const ImageDifference d = compareImages(base, image, kDisplayStep);
        const double within = 1.0 - d.fractionOver();
        table << "\n  k = " << std::setw(2) << k << ": " << percent(within) << " within 1/255 ("
              << d.over << " of " << d.pixels << " pixels over), largest " << d.largest * 255
              << "/255";
        if (within < share)
            failures << "\n  k = " << k << ": " << percent(within) << " within 1/255, "
                     << writeFailure(base, image, kDisplayStep,
                                     std::string(what) + "-1e" + std::to_string(k) + "-" +
                                         test::label(precision));
    }
    std::cout << "[ MEASURED ] " << test::label(precision) << " " << what << " by 10^k (needs "
              << percent(share) << " within 1/255):" << table.str() << std::endl;
    EXPECT_TRUE(failures.str().empty()) << "below " << percent(share) << ":" << failures.str();
}

Scene scaledByPowerOfTen(const Scene& s, int k) {
    return scaledScene(s, std::pow(10.0, k));
}

TEST(NumericsInvariance, ScaleByPowerOfTenFloat_SeedScene_999PerMilleWithinDisplayStep) {
    checkNearlyInvariant(Precision::Float, -4, 4, 0.999, "scale", scaledByPowerOfTen);
}

TEST(NumericsInvariance, ScaleByPowerOfTenDouble_SeedScene_9999PerTenThousandWithinDisplayStep) {
    checkNearlyInvariant(Precision::Double, -8, 8, 0.9999, "scale", scaledByPowerOfTen);
}

// ---- translation ------------------------------------------------------------------

// 10^k (1,1,1): each component a whole multiple of 1.0, twice the seed's checker
// size, so the checker pattern moves with the scene (scene_transform.h).
Scene movedByPowerOfTen(const Scene& s, int k) {
    const double offset = std::pow(10.0, k);
    return translatedScene(s, Vec3(offset, offset, offset));
}

TEST(NumericsInvariance, TranslateByPowerOfTenFloat_SeedScene_999PerMilleWithinDisplayStep) {
    checkNearlyInvariant(Precision::Float, 2, 5, 0.999, "translation", movedByPowerOfTen);
}

TEST(NumericsInvariance,
     TranslateByPowerOfTenDouble_SeedScene_9999PerTenThousandWithinDisplayStep) {
    checkNearlyInvariant(Precision::Double, 2, 9, 0.9999, "translation", movedByPowerOfTen);
}

// ---- float against double -----------------------------------------------------------

TEST(NumericsInvariance, FloatAgainstDouble_SeedScene_AtMostOnePerMilleOverTwoSteps) {
    const Image f = test::renderImage(test::seedScene(640, 480, Precision::Float));
    const Image d = test::renderImage(test::seedScene(640, 480, Precision::Double));
    const ImageDifference diff = compareImages(d, f, 2 * kDisplayStep);
    std::cout << "[ MEASURED ] seed 640x480, float against double: " << diff.over << " of "
              << diff.pixels << " pixels (" << percent(diff.fractionOver())
              << ") differ by more than 2/255, largest " << diff.largest * 255 << "/255"
              << std::endl;
    EXPECT_LE(diff.fractionOver(), 0.001)
        << writeFailure(d, f, 2 * kDisplayStep, "seed-float-vs-double");
}

// The seed's floor touches the cell boundary plane y = -0.5 at (0, -0.5, 0)
// and falls below it by only (x^2 + z^2) / 2r around there: 1e-11 a few
// pixels away at 640x480. Float gave the pixel there the wrong cell (162/255
// off double) while the camera's frame dropped 6e-11 of the floor's centre
// (frameOriginNear() in tracer.cpp). Checked from the seed's camera and from
// one moved to coordinates with all their bits, as orbiting leaves them.
TEST(NumericsInvariance, FloatAgainstDouble_SeedFloorWhereItTouchesACellBoundary_SameCells) {
    for (const Vec3 eye :
         {Vec3(0.0, 0.35, -1.0), Vec3(0.1234567891, 0.3456789123, -1.0987654321)}) {
        Scene scene = test::seedScene(640, 480, Precision::Float);
        scene.camera.position = eye;
        const Image f = test::renderImage(scene);
        scene.render.precision = Precision::Double;
        const Image d = test::renderImage(scene);
        const auto seen = projectToImage(scene.camera, 640, 480, Vec3(0.0, -0.5, 0.0));
        ASSERT_TRUE(seen) << "the tangent point is behind the camera";
        const int centreX = int(seen->x), centreY = int(seen->y);
        ASSERT_TRUE(centreX >= 0 && centreX < 640 && centreY >= 0 && centreY < 480)
            << "the tangent point is out of the picture: (" << centreX << ", " << centreY << ")";
        test::Worst largest;
        for (int y = std::max(0, centreY - 20); y < std::min(480, centreY + 20); ++y)
            for (int x = std::max(0, centreX - 30); x < std::min(640, centreX + 30); ++x)
                largest.note(displayDifference(f.pixel(x, y), d.pixel(x, y)),
                             std::to_string(x) + ", " + std::to_string(y));
        std::cout << "[ MEASURED ] seed 640x480 from " << test::str(eye)
                  << ", around the floor's tangent point (" << centreX << ", " << centreY
                  << "), float against double: largest " << largest.value * 255 << "/255 at ("
                  << largest.where << ")" << std::endl;
        EXPECT_LE(largest.value, 2 * kDisplayStep) << "at pixel (" << largest.where << ")";
    }
}

// The primary ray through pixel (i, j)'s centre, in T, by SPEC §1.
template <typename T>
Vec<T> pixelCentreDirection(const PreparedScene<T>& s, const Scene& scene, int i, int j) {
    const T tanHalf = T(std::tan(scene.camera.vfovDegrees * M_PI / 360.0));
    const int width = scene.render.width, height = scene.render.height;
    const T aspect = T(double(width) / double(height));
    const T x = ((T(i) + T(0.5)) / T(width) * T(2) - T(1)) * tanHalf * aspect;
    const T y = (T(1) - (T(j) + T(0.5)) / T(height) * T(2)) * tanHalf;
    return glm::normalize(s.camera.forward + x * s.camera.right + y * s.camera.up);
}

// What the primary ray through a pixel meets and, per light, whether the tracer
// would trace a shadow ray there (N.L > 0) and what it returns.
template <typename T>
struct PixelShadow {
    int sphere = -1;
    bool tested[4] = {};
    T S[4] = {};
};

template <typename T>
PixelShadow<T> pixelShadow(const PreparedScene<T>& s, const Scene& scene, int i, int j) {
    PixelShadow<T> out;
    const Vec<T> d = pixelCentreDirection(s, scene, i, j);
    const auto hit = closestHit<T>(s, Ray<T>{s.camera.origin, d, -1, false, true});
    if (!hit) return out;
    out.sphere = hit->sphere;
    const Vec<T> p = s.camera.origin + hit->t * d;
    const Vec<T> outward = glm::normalize(p - s.spheres.centre[hit->sphere]);
    const Vec<T> n = glm::dot(d, outward) > T(0) ? -outward : outward;
    for (std::size_t j2 = 0; j2 < s.lights.size() && j2 < 4; ++j2) {
        const Vec<T> l = glm::normalize(s.lights[j2].position - p);
        if (!(glm::dot(n, l) > T(0))) continue;
        out.tested[j2] = true;
        out.S[j2] = test::shadowTransmittance(s, p, hit->sphere, s.lights[j2].position);
    }
    return out;
}

TEST(NumericsInvariance, FloatAgainstDouble_SeedScene_NoPixelFalselyInShadow) {
    const Scene scene = test::seedScene(640, 480, Precision::Float);
    const PreparedScene<float> sf = prepareScene<float>(scene);
    const PreparedScene<double> sd = prepareScene<double>(scene);
    ASSERT_LE(sf.lights.size(), 4u);
    long compared = 0, falselyShadowed = 0, falselyLit = 0;
    std::string first;
    for (int j = 0; j < scene.render.height; ++j) {
        for (int i = 0; i < scene.render.width; ++i) {
            const PixelShadow<float> f = pixelShadow(sf, scene, i, j);
            const PixelShadow<double> d = pixelShadow(sd, scene, i, j);
            if (f.sphere < 0 || f.sphere != d.sphere) continue;
            for (std::size_t l = 0; l < sf.lights.size(); ++l) {
                if (!f.tested[l] || !d.tested[l]) continue;
                ++compared;
                if (f.S[l] < 1.0f && d.S[l] == 1.0) {
                    if (falselyShadowed++ == 0)
                        first = "pixel (" + std::to_string(i) + ", " + std::to_string(j) +
                                "), sphere " + scene.spheres[f.sphere].name + ", light " +
                                std::to_string(l) + ": float S " + std::to_string(f.S[l]);
                }
                falselyLit += f.S[l] == 1.0f && d.S[l] < 1.0;
            }
        }
    }
    std::cout << "[ MEASURED ] seed 640x480: " << compared
              << " (pixel, light) pairs with a shadow ray in both precisions; in shadow only in "
                 "float: "
              << falselyShadowed << ", lit only in float: " << falselyLit << std::endl;
    EXPECT_EQ(falselyShadowed, 0) << "first: " << first;
}

}  // namespace
}  // namespace whitted
