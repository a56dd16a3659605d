// Numerics tests: no NaN or Inf anywhere, no sentinel distance that
// overflows float, and hand-computed pixels for the awkward configurations: a
// camera or a light inside a sphere, camera up nearly parallel to the view, a light
// between a lit sphere and an occluder behind it, total internal reflection.
//
// Hand-computed pixels are compared to 1e-5 relative (plus 1e-7 absolute), as in
// test_tracer.cpp: the image stores float and a float render loses a few ulps per
// operation. Scenes for the hand-computed pixels are 1x1 images from a camera
// looking down +z, whose only ray is the centre ray, exactly the forward vector.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/scene_transform.h"
#include "support/numerics_support.h"

namespace whitted {
namespace {

using test::Rng;

const Precision kPrecisions[] = {Precision::Float, Precision::Double};

// Pixels with at least one NaN or infinite channel.
long nonFinitePixels(const Image& image) {
    long bad = 0;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
        bad += !(std::isfinite(image.rgb[i]) && std::isfinite(image.rgb[i + 1]) &&
                 std::isfinite(image.rgb[i + 2]));
    return bad;
}

Vec3 onlyPixel(const Scene& s) {
    const Image image = test::renderImage(s);
    const float* p = image.pixel(0, 0);
    return {p[0], p[1], p[2]};
}

// ---- no NaN or Inf: random scenes ----------------------------------------------------

// A random scene of balls on a floor sphere, built to be awkward: glass with ior
// from 0.1 to 10, mirrors, balls tangent to the floor and to each other, balls
// intersecting, a camera on a sphere's surface or inside a ball, lights inside
// glass or on a surface, intensities up to 1e6. `chain` scenes have no material
// that both reflects and refracts, so one ray never splits into two and
// max_depth may go up to 64; the others stop at depth 6.
Scene randomScene(Rng& rng, Precision precision, bool chain) {
    auto colour = [&](double top) {
        return Vec3(test::uniform(rng, 0, top), test::uniform(rng, 0, top),
                    test::uniform(rng, 0, top));
    };
    auto pick = [&](int n) { return int(std::uniform_int_distribution<int>(0, n - 1)(rng)); };
    Scene s;
    s.render.width = 40;
    s.render.height = 30;
    s.render.maxDepth = chain ? 16 + pick(49) : pick(7);
    s.render.precision = precision;
    s.background = colour(1);
    s.ambient = colour(0.2);

    Material floor = test::makeMaterial("floor", colour(1), test::uniform(rng, 0, 1), 0);
    floor.reflectivity = test::uniform(rng, 0, 0.5);
    if (pick(2)) floor.checker = Checker{colour(1), test::logUniform(rng, 0.05, 2)};
    s.materials.push_back(floor);
    const double floorRadius = test::logUniform(rng, 1e2, 1e6);
    const Vec3 floorCentre{0, -floorRadius, 0};
    s.spheres.push_back(test::makeSphere("floor", floorCentre, floorRadius, "floor"));

    const int balls = 3 + pick(6);
    for (int i = 0; i < balls; ++i) {
        const std::string name = "ball" + std::to_string(i);
        Material m = test::makeMaterial(name, colour(1), test::uniform(rng, 0, 2));
        m.shininess = test::uniform(rng, 1, 500);  // whole and fractional exponents
        switch (pick(3)) {
            case 0:  // glass
                m.diffuse = colour(0.3);
                m.transparency = test::uniform(rng, 0.05, 1);
                m.ior = test::logUniform(rng, 0.1, 10);
                m.reflectivity = chain ? 0 : test::uniform(rng, 0, 1 - m.transparency);
                break;
            case 1:  // mirror
                m.reflectivity = test::uniform(rng, 0.3, 1);
                break;
            default:  // painted
                m.reflectivity = test::uniform(rng, 0, 0.3);
                break;
        }
        s.materials.push_back(m);
        const double r = test::logUniform(rng, 0.05, 1.5);
        Vec3 c;
        const int mode = i == 0 ? 0 : pick(4);
        if (mode == 0) {  // resting on the floor: tangent to it
            const Vec3 up = glm::normalize(
                Vec3(test::uniform(rng, -4, 4), floorRadius, test::uniform(rng, 0, 8)));
            c = floorCentre + (floorRadius + r) * up;
        } else if (mode == 1) {  // tangent to an earlier ball
            const Sphere& other = s.spheres[1 + pick(i)];
            c = other.center + (other.radius + r) * test::randomUnit(rng);
        } else if (mode == 2) {  // intersecting an earlier ball
            const Sphere& other = s.spheres[1 + pick(i)];
            c = other.center +
                test::uniform(rng, 0.2, 0.95) * (other.radius + r) * test::randomUnit(rng);
        } else {
            c = {test::uniform(rng, -4, 4), test::uniform(rng, -0.5, 3), test::uniform(rng, 0, 8)};
        }
        s.spheres.push_back(test::makeSphere(name, c, r, name));
    }

    const Sphere& target = s.spheres[1 + pick(balls)];
    switch (pick(4)) {
        case 0:  // on a ball's surface, looking anywhere
            s.camera.position = target.center + target.radius * test::randomUnit(rng);
            s.camera.lookAt = s.camera.position + test::randomUnit(rng);
            break;
        case 1:  // inside a ball
            s.camera.position =
                target.center + test::uniform(rng, 0, 0.95) * target.radius * test::randomUnit(rng);
            s.camera.lookAt = s.camera.position + test::randomUnit(rng);
            break;
        case 2: {  // on the floor, looking along it
            const Vec3 up = glm::normalize(
                Vec3(test::uniform(rng, -2, 2), floorRadius, test::uniform(rng, -2, 2)));
            s.camera.position = floorCentre + floorRadius * up;
            s.camera.lookAt =
                s.camera.position + Vec3(test::uniform(rng, -1, 1), test::uniform(rng, -1e-3, 0.3),
                                         test::uniform(rng, 0.2, 1));
            break;
        }
        default:
            s.camera.position = {test::uniform(rng, -3, 3), test::uniform(rng, 0.05, 3),
                                 test::uniform(rng, -6, -1)};
            s.camera.lookAt = target.center;
            break;
    }
    s.camera.up = pick(2) ? Vec3(0, 1, 0) : test::randomUnit(rng);
    s.camera.vfovDegrees = test::uniform(rng, 10, 170);

    const int lights = 1 + pick(3);
    for (int j = 0; j < lights; ++j) {
        const Sphere& host = s.spheres[1 + pick(balls)];
        Vec3 position;
        switch (pick(3)) {
            case 0:  // inside a ball
                position =
                    host.center + test::uniform(rng, 0, 0.9) * host.radius * test::randomUnit(rng);
                break;
            case 1:  // on a ball's surface
                position = host.center + host.radius * test::randomUnit(rng);
                break;
            default:
                position = {test::uniform(rng, -10, 10), test::uniform(rng, 0, 10),
                            test::uniform(rng, -10, 10)};
                break;
        }
        s.lights.push_back(test::makeLight("light" + std::to_string(j), position, colour(1),
                                           test::logUniform(rng, 1e-3, 1e6)));
    }
    return s;
}

void checkRandomScenesFinite(Precision precision) {
    const std::uint64_t seed = test::propertySeed();
    Rng rng(seed);
    constexpr int kScenes = 400;
    // Half the scenes are also scaled as a whole by 10^U(-3, 3) (float) or 10^U(-8, 8).
    const double scaleDecades = precision == Precision::Float ? 3 : 8;
    int rendered = 0, failed = 0;
    long badPixels = 0, hitPixels = 0, allPixels = 0;
    std::string firstFailure;
    for (int n = 0; n < kScenes; ++n) {
        Scene scene;
        do {
            scene = randomScene(rng, precision, n % 2 == 0);
            if (n % 4 >= 2)
                scene = scaledScene(
                    scene, std::pow(10.0, test::uniform(rng, -scaleDecades, scaleDecades)));
        } while (validateScene(scene));  // rare: a random up parallel to the view
        ++rendered;
        const Image image = test::renderImage(scene);
        const glm::vec3 background(scene.background);
        for (std::size_t i = 0; i < image.rgb.size(); i += 3)
            hitPixels += glm::vec3(image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]) != background;
        allPixels += long(image.rgb.size() / 3);
        const long bad = nonFinitePixels(image);
        if (bad == 0) continue;
        badPixels += bad;
        if (failed++ == 0)
            firstFailure = "scene " + std::to_string(n) + " (" + std::to_string(bad) +
                           " pixels):\n" + sceneToJson(scene);
    }
    std::cout << "[ MEASURED ] " << test::label(precision) << ": " << failed << " of " << rendered
              << " random scenes with NaN or Inf pixels (" << badPixels << " pixels); "
              << 100.0 * double(hitPixels) / double(allPixels) << " % of pixels not background"
              << std::endl;
    EXPECT_EQ(failed, 0) << "first failing " << firstFailure;
}

TEST(NumericsRobustness, RandomScenesFloat_GlassMirrorsGrazing_EveryChannelFinite) {
    checkRandomScenesFinite(Precision::Float);
}

TEST(NumericsRobustness, RandomScenesDouble_GlassMirrorsGrazing_EveryChannelFinite) {
    checkRandomScenesFinite(Precision::Double);
}

// ---- no NaN or Inf: the limits of the scene format -----------------------------------

// A glass ball and a painted ball on the seed's floor, one light; each case
// below pushes one value to what validateScene() still accepts (any finite
// positive length, any finite non-negative colour or intensity, ior > 0,
// max_depth 64).
Scene limitsBase(Precision precision) {
    Scene s;
    s.camera.position = {0, 0.5, -3};
    s.camera.lookAt = {0, 0.3, 0};
    s.render.width = 32;
    s.render.height = 24;
    s.render.maxDepth = 8;
    s.render.precision = precision;
    s.background = {0.1, 0.2, 0.3};
    s.materials = {test::makeMaterial("glass", {0.05, 0.05, 0.05}, 1, 0.1, 0.85, 1.5),
                   test::makeMaterial("paint", {0.8, 0.2, 0.1}, 1, 0.2),
                   test::makeMaterial("floor", {0.7, 0.7, 0.7}, 0, 0.3)};
    s.materials[2].checker = Checker{{0.1, 0.1, 0.1}, 0.5};
    s.spheres = {test::makeSphere("glass", {-0.6, 0.1, 0.5}, 0.6, "glass"),
                 test::makeSphere("paint", {0.7, 0, 1.2}, 0.5, "paint"),
                 test::makeSphere("floor", {0, -99999.5, 0}, 99999, "floor")};
    s.lights = {test::makeLight("key", {5, 5, -10})};
    return s;
}

struct LimitCase {
    const char* name;
    void (*apply)(Scene&);
};

const LimitCase kLimitCases[] = {
    {"ball of radius 1e-300 in view",
     [](Scene& s) {
         s.spheres.push_back(test::makeSphere("tiny", {0, 0.3, 0}, 1e-300, "paint"));
     }},
    {"ball of radius 1e-30 in view",
     [](Scene& s) {
         s.spheres.push_back(test::makeSphere("tiny", {0, 0.3, 0}, 1e-30, "paint"));
     }},
    {"sphere of radius 1e30 ahead, centre 3e30 away",
     [](Scene& s) {
         s.spheres.push_back(test::makeSphere("huge", {0, 0, 3e30}, 1e30, "paint"));
     }},
    {"sphere of radius 1e300 ahead, centre 3e300 away",
     [](Scene& s) {
         s.spheres.push_back(test::makeSphere("huge", {0, 0, 3e300}, 1e300, "paint"));
     }},
    {"everything inside a glass sphere of radius 1e30",
     [](Scene& s) {
         s.spheres.push_back(test::makeSphere("huge", {0, 0, 0}, 1e30, "glass"));
     }},
    {"everything inside a glass sphere of radius 1e300",
     [](Scene& s) {
         s.spheres.push_back(test::makeSphere("huge", {0, 0, 0}, 1e300, "glass"));
     }},
    {"camera 1e30 away",
     [](Scene& s) {
         s.camera.position = {0, 0, -1e30};
     }},
    // Not 1e300: validateScene() squares the view vector and refuses a camera
    // more than ~1e154 from its look_at as "up parallel to the view".
    {"camera 1e150 away",
     [](Scene& s) {
         s.camera.position = {0, 0, -1e150};
     }},
    {"light 1e30 away",
     [](Scene& s) {
         s.lights[0].position = {1e30, 1e30, -1e30};
     }},
    {"light 1e300 away",
     [](Scene& s) {
         s.lights[0].position = {1e300, 1e300, -1e300};
     }},
    {"light of intensity 1e30", [](Scene& s) { s.lights[0].intensity = 1e30; }},
    {"light of intensity 1e300", [](Scene& s) { s.lights[0].intensity = 1e300; }},
    {"specular 1e30, shininess 1e300",
     [](Scene& s) {
         s.materials[1].specular = 1e30;
         s.materials[1].shininess = 1e300;
     }},
    {"ior 1e-300 and 1e300",
     [](Scene& s) {
         s.materials[0].ior = 1e-300;
         s.materials.push_back(test::makeMaterial("dense", {0, 0, 0}, 0, 0, 1, 1e300));
         s.spheres[1].material = "dense";
     }},
    {"ior 0.1 and 10 at max_depth 64",
     [](Scene& s) {
         s.materials[0].ior = 0.1;
         s.materials[0].reflectivity = 0;
         s.materials[1] = test::makeMaterial("paint", {0, 0, 0}, 0, 0, 1, 10);
         s.render.maxDepth = 64;
     }},
    {"checker size 1e-300", [](Scene& s) { s.materials[2].checker->size = 1e-300; }},
    {"checker size 1e300", [](Scene& s) { s.materials[2].checker->size = 1e300; }},
    {"vfov 1e-10 degrees", [](Scene& s) { s.camera.vfovDegrees = 1e-10; }},
    {"vfov 179.9999 degrees", [](Scene& s) { s.camera.vfovDegrees = 179.9999; }},
    {"two facing mirrors at max_depth 64",
     [](Scene& s) {
         s.materials[0].reflectivity = 0;  // no ray splits in two: 64 bounces stay cheap
         s.materials.push_back(test::makeMaterial("mirror", {0.1, 0.1, 0.1}, 1, 1));
         s.spheres.push_back(test::makeSphere("left", {-1e6 - 1, 0.3, 0}, 1e6, "mirror"));
         s.spheres.push_back(test::makeSphere("right", {1e6 + 1, 0.3, 0}, 1e6, "mirror"));
         s.render.maxDepth = 64;
     }},
};

TEST(NumericsRobustness, FormatLimits_EachCase_EveryChannelFinite) {
    for (const Precision precision : kPrecisions) {
        for (const LimitCase& c : kLimitCases) {
            Scene scene = limitsBase(precision);
            c.apply(scene);
            if (const auto problem = validateScene(scene)) {
                ADD_FAILURE() << c.name << ": the loader refuses it (" << problem->jsonPath << ": "
                              << problem->reason << "); the case must stay within the format";
                continue;
            }
            const long bad = nonFinitePixels(test::renderImage(scene));
            std::cout << "[ MEASURED ] " << test::label(precision) << ", " << c.name << ": " << bad
                      << " of " << scene.render.width * scene.render.height << " pixels NaN or Inf"
                      << std::endl;
            EXPECT_EQ(bad, 0) << test::label(precision) << ", " << c.name;
        }
    }
}

// ---- no sentinel that overflows float ------------------------------------------------

// A sphere 1e30 away in float: rendering it or the background are both
// acceptable (its squared distance, 1e60, is not a float), Inf and NaN are not.
// In double it must be rendered: with the light at the camera, the centre pixel
// of an odd-sized image is kd (ambient + c) exactly (N.L = 1).
TEST(NumericsRobustness, FarSphere_At1e30_RenderedOrBackgroundNeverInf) {
    for (const Precision precision : kPrecisions) {
        Scene s = test::centreRayScene(precision);
        s.render.width = 33;
        s.render.height = 25;  // pixel (16, 12) is exactly the centre ray
        s.background = {0.25, 0.5, 0.125};
        s.ambient = {0.1, 0.1, 0.1};
        s.materials = {test::makeMaterial("m", {0.5, 0.25, 1})};
        s.spheres = {test::makeSphere("far", {0, 0, 1e30}, 5e29, "m")};
        s.lights = {test::makeLight("at camera", {0, 0, 0}, {1, 1, 1}, 2)};
        const Image image = test::renderImage(s);
        EXPECT_EQ(nonFinitePixels(image), 0) << test::label(precision);
        const float* p = image.pixel(16, 12);
        const Vec3 centre{p[0], p[1], p[2]};
        const Vec3 lit{0.5 * 2.1, 0.25 * 2.1, 1 * 2.1};
        const Vec3 background(glm::vec3(s.background));  // as the image stores it
        long sphere = 0;
        for (std::size_t i = 0; i < image.rgb.size(); i += 3)
            sphere += Vec3(image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]) != background;
        std::cout << "[ MEASURED ] " << test::label(precision) << ": sphere 1e30 away covers "
                  << sphere << " of 825 pixels" << std::endl;
        if (precision == Precision::Double || centre != background)
            test::expectColour(centre, lit, test::label(precision) + ", centre pixel");
    }
}

template <typename T>
void checkHugeFiniteDistances(double distance) {
    Scene scene = test::centreRayScene(test::precisionOf<T>());
    scene.materials = {test::makeMaterial("m", {1, 1, 1})};
    scene.spheres = {test::makeSphere("far", {0, 0, distance}, distance / 10, "m")};
    const PreparedScene<T> s = prepareScene<T>(scene);
    const Vec<T> forward(0, 0, 1);
    const Ray<T> ray{s.camera.origin, forward, -1, false, true};
    const double expected = distance * 0.9;
    const auto byDefault = closestHit<T>(s, ray);
    ASSERT_TRUE(byDefault) << "default tMax (infinity) lost a hit at " << expected;
    EXPECT_NEAR(double(byDefault->t), expected, expected * 1e-5);
    const auto toInfinity = closestHit<T>(s, ray, std::numeric_limits<T>::infinity());
    ASSERT_TRUE(toInfinity);
    EXPECT_EQ(toInfinity->t, byDefault->t);
    const auto toLargest = closestHit<T>(s, ray, std::numeric_limits<T>::max());
    ASSERT_TRUE(toLargest) << "tMax = the largest finite value lost a hit at " << expected;
    EXPECT_EQ(toLargest->t, byDefault->t);
    EXPECT_TRUE(closestHit<T>(s, ray, T(distance * 1.2))) << "tMax just past the hit";
    EXPECT_FALSE(closestHit<T>(s, ray, T(distance * 0.8))) << "tMax short of the hit";
}

// Hits at t = 1.35e19 in float (the centre distance squared, 2.25e38, is still a
// float) and 9e149 in double (likewise): a sentinel "far" distance such as 1e30 or
// FLT_MAX converted to double would lose or misorder them, an infinite one would not.
TEST(NumericsRobustness, ClosestHit_HugeButFiniteT_FoundAndComparedWithTMax) {
    checkHugeFiniteDistances<float>(1e6);
    checkHugeFiniteDistances<float>(1.5e19);
    checkHugeFiniteDistances<double>(1.5e19);
    checkHugeFiniteDistances<double>(1e150);
}

template <typename T>
void checkMissIsBackground() {
    Scene scene = test::centreRayScene(test::precisionOf<T>());
    scene.background = {0.3, 0.2, 0.1};
    scene.ambient = {1, 1, 1};
    scene.materials = {test::makeMaterial("m", {1, 1, 1}, 1, 0.5)};
    scene.spheres = {test::makeSphere("beside", {0, 0, 5}, 1, "m")};
    const PreparedScene<T> s = prepareScene<T>(scene);
    RayCounts counts;
    const Vec<T> away(0, 0, -1);
    EXPECT_EQ(traceRay<T>(s, Ray<T>{s.camera.origin, away, -1, false, true}, 0, counts),
              Vec<T>(scene.background));
    EXPECT_EQ(traceRay<T>(s, Ray<T>{s.camera.origin, away, -1, false, false}, 3, counts),
              Vec<T>(scene.background));
    // A whole image of misses: every pixel is the background, bit for bit.
    scene.spheres.clear();
    scene.render.width = 16;
    scene.render.height = 12;
    const Image image = test::renderImage(scene);
    const glm::vec3 bg(Vec<T>(scene.background));
    long other = 0;
    for (std::size_t i = 0; i < image.rgb.size(); i += 3)
        other += glm::vec3(image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]) != bg;
    EXPECT_EQ(other, 0);
}

TEST(NumericsRobustness, Miss_AnyPrecision_ReturnsBackgroundExactly) {
    checkMissIsBackground<float>();
    checkMissIsBackground<double>();
}

// ---- camera and lights inside spheres ------------------------------------------------

// The camera at the centre of an opaque sphere of radius 10 sees its inside: the
// centre ray meets it at P = (0,0,10), normal flipped to (0,0,-1). With the light
// inside at (1,2,3): L = (1,2,-7)/sqrt(54), N.L = 7/sqrt(54), colour
// kd (ambient + c N.L). With the light outside, the sphere shadows it: kd ambient.
TEST(NumericsRobustness, CameraInsideSphere_SeesItsInsideLitFromWithin) {
    for (const Precision precision : kPrecisions) {
        Scene s = test::centreRayScene(precision);
        s.ambient = {0.1, 0.1, 0.1};
        s.materials = {test::makeMaterial("m", {0.5, 0.6, 0.7})};
        s.spheres = {test::makeSphere("room", {0, 0, 0}, 10, "m")};
        s.lights = {test::makeLight("inside", {1, 2, 3})};
        const double nl = 7 / std::sqrt(54.0);
        test::expectColour(onlyPixel(s), Vec3(0.5, 0.6, 0.7) * (0.1 + nl),
                           test::label(precision) + ", light inside");
        s.lights = {test::makeLight("outside", {0, 0, -20})};
        test::expectColour(onlyPixel(s), Vec3(0.5, 0.6, 0.7) * 0.1,
                           test::label(precision) + ", light outside");
    }
}

// A light at the centre of a glass ball (radius 1, transparency 0.5) lights a
// white ball outside it through the glass. The camera at (0,0,2), outside the
// glass and looking down +z, sees the white ball (centre (0,0,5), radius 1) at
// P = (0,0,4), N = (0,0,-1); L = (0,0,-1), N.L = 1; the shadow ray crosses the
// glass once: S = 0.5. Colour kd (ambient + 0.5 c). An opaque ball there: kd ambient.
TEST(NumericsRobustness, LightInsideTransparentSphere_LightsOutsideByItsTransparency) {
    for (const Precision precision : kPrecisions) {
        Scene s = test::centreRayScene(precision, {0, 0, 2}, {0, 0, 5});
        s.ambient = {0.1, 0.1, 0.1};
        s.materials = {test::makeMaterial("white", {0.8, 0.9, 1.0}),
                       test::makeMaterial("glass", {0, 0, 0}, 0, 0, 0.5, 1.5)};
        s.spheres = {test::makeSphere("lamp shade", {0, 0, 0}, 1, "glass"),
                     test::makeSphere("target", {0, 0, 5}, 1, "white")};
        s.lights = {test::makeLight("lamp", {0, 0, 0}, {1, 1, 1}, 2)};
        test::expectColour(onlyPixel(s), Vec3(0.8, 0.9, 1.0) * (0.1 + 0.5 * 2),
                           test::label(precision) + ", glass shade");
        s.materials[1].transparency = 0;
        test::expectColour(onlyPixel(s), Vec3(0.8, 0.9, 1.0) * 0.1,
                           test::label(precision) + ", opaque shade");
    }
}

// Shadow rays stop at the light: the light at (0,0,2) between the lit ball
// (P = (0,0,4), N = L = (0,0,-1)) and an occluder behind the light (centre
// (0,0,1), radius 0.5). The camera at (0,0,1.8) looks down +z past the light.
// The occluder's roots along the shadow ray are 2.5 and 3.5, beyond the light's
// distance 2: no shadow, colour kd (ambient + c).
TEST(NumericsRobustness, OccluderBehindLight_DoesNotShadow) {
    for (const Precision precision : kPrecisions) {
        Scene s = test::centreRayScene(precision, {0, 0, 1.8}, {0, 0, 5});
        s.ambient = {0.1, 0.1, 0.1};
        s.materials = {test::makeMaterial("white", {0.8, 0.9, 1.0})};
        s.spheres = {test::makeSphere("lit", {0, 0, 5}, 1, "white"),
                     test::makeSphere("occluder", {0, 0, 1}, 0.5, "white")};
        s.lights = {test::makeLight("between", {0, 0, 2}, {1, 1, 1}, 1.5)};
        test::expectColour(onlyPixel(s), Vec3(0.8, 0.9, 1.0) * (0.1 + 1.5), test::label(precision));
    }
}

// ---- camera up nearly parallel to the view -----------------------------------------------

// up within 1e-6, 1e-9 and 1e-11 radians of the view direction (or of its
// opposite); validateScene() accepts down to ~1e-12. The basis must be
// orthonormal to 1e-12 in double (and to 4 float epsilons in float, where it is the
// double basis rounded), right must be on the side of cross(up, forward), and a
// render must be free of NaN.
TEST(NumericsRobustness, UpNearlyParallelToView_OrthonormalBasisAndFiniteRender) {
    const std::uint64_t seed = test::propertySeed();
    Rng rng(seed);
    constexpr int kTrials = 8;
    bool ok = true;
    std::ostringstream table, worstCases;
    for (const double angle : {1e-6, 1e-9, 1e-11}) {
        for (const double side : {1.0, -1.0}) {
            // Per precision: trials whose basis is off, and the largest deviation.
            int off[2] = {0, 0}, wrongSide[2] = {0, 0}, refused = 0, badRenders = 0;
            test::Worst worst[2];
            for (int trial = 0; trial < kTrials; ++trial) {
                const Vec3 f = test::randomUnit(rng);
                const Vec3 across = test::randomPerpendicular(rng, f);
                Scene scene = test::centreRayScene(Precision::Double);
                scene.camera.position = test::randomUnit(rng) * test::uniform(rng, 0, 10);
                scene.camera.lookAt = scene.camera.position + f;
                scene.camera.up = side * std::cos(angle) * f + std::sin(angle) * across;
                std::ostringstream where;
                where.precision(17);
                where << "angle " << angle << (side < 0 ? " from the opposite" : "") << ", trial "
                      << trial << ": forward " << test::str(f) << ", up "
                      << test::str(scene.camera.up);
                if (validateScene(scene)) {
                    ++refused;
                    continue;
                }
                const auto checkBasis = [&](const auto& b, double tol, int i) {
                    const Vec3 r(b.right), u(b.up), fw(b.forward);
                    const double dev =
                        std::max({std::fabs(glm::length(r) - 1), std::fabs(glm::length(u) - 1),
                                  std::fabs(glm::length(fw) - 1), std::fabs(glm::dot(r, u)),
                                  std::fabs(glm::dot(r, fw)), std::fabs(glm::dot(u, fw))});
                    worst[i].note(dev, where.str());
                    off[i] += !(dev <= tol);
                    wrongSide[i] += !(glm::dot(r, glm::cross(scene.camera.up, f)) > 0);
                };
                checkBasis(prepareScene<double>(scene).camera, 1e-12, 0);
                checkBasis(prepareScene<float>(scene).camera,
                           4 * std::numeric_limits<float>::epsilon(), 1);
                scene.render.width = 16;
                scene.render.height = 12;
                scene.materials = {test::makeMaterial("m", {0.5, 0.5, 0.5}, 1)};
                scene.spheres = {test::makeSphere("ahead", scene.camera.lookAt, 0.3, "m")};
                scene.lights = {test::makeLight("l", scene.camera.position + across)};
                for (const Precision precision : kPrecisions) {
                    scene.render.precision = precision;
                    badRenders += nonFinitePixels(test::renderImage(scene)) > 0;
                }
            }
            table << "\n  angle " << angle << (side < 0 ? " from -forward" : " from forward")
                  << ": double basis off (> 1e-12) in " << off[0] << "/" << kTrials << " (largest "
                  << worst[0].value << "), float basis off (> 4 eps) in " << off[1] << "/"
                  << kTrials << " (largest " << worst[1].value << "), right on the wrong side "
                  << wrongSide[0] + wrongSide[1] << ", refused by validateScene " << refused
                  << ", renders with NaN/Inf " << badRenders;
            if (off[0] || off[1] || wrongSide[0] || wrongSide[1] || refused || badRenders) {
                ok = false;
                worstCases << "\n  worst double: " << worst[0].value << " at " << worst[0].where
                           << "\n  worst float: " << worst[1].value << " at " << worst[1].where;
            }
        }
    }
    std::cout << "[ MEASURED ] up nearly parallel to the view:" << table.str() << std::endl;
    EXPECT_TRUE(ok) << table.str() << worstCases.str();
}

// ---- total internal reflection -----------------------------------------------------------

// The camera inside a glass ball (centre (0.9,0,0), radius 1, ior 1.5) looks down
// +z: the centre ray passes 0.9 from the centre, so it meets the surface at
// sin(i) = 0.9, beyond the critical angle (sin = 1/1.5), and so does every
// reflection of it (a chord keeps its distance from the centre). No lights;
// each hit adds ambient * kd, and each bounce is weighted by kr + kt, the TIR
// share following the reflected ray (SPEC §3): the pixel is
// ambient kd sum_{d=0}^{max_depth} (kr + kt)^d. Dropping the TIR share would give
// kr^d instead.
TEST(NumericsRobustness, TotalInternalReflection_RefractedShareFollowsReflection) {
    struct Case {
        double kr, kt;
        int depth;
    };
    for (const Precision precision : kPrecisions) {
        for (const Case c : {Case{0.25, 0.5, 5}, Case{0.1, 0.9, 64}}) {
            Scene s = test::centreRayScene(precision);
            s.ambient = {0.5, 0.25, 0.125};
            s.render.maxDepth = c.depth;
            s.materials = {test::makeMaterial("glass", {0.02, 0.04, 0.08}, 0, c.kr, c.kt, 1.5)};
            s.spheres = {test::makeSphere("glass", {0.9, 0, 0}, 1, "glass")};
            double sum = 0;
            for (int d = c.depth; d >= 0; --d) sum = 1 + (c.kr + c.kt) * sum;
            const Vec3 expected = Vec3(0.5 * 0.02, 0.25 * 0.04, 0.125 * 0.08) * sum;
            const Vec3 pixel = onlyPixel(s);
            std::ostringstream what;
            what << test::label(precision) << ", kr " << c.kr << ", kt " << c.kt << ", max_depth "
                 << c.depth;
            EXPECT_TRUE(std::isfinite(pixel.x) && std::isfinite(pixel.y) && std::isfinite(pixel.z))
                << what.str();
            test::expectColour(pixel, expected, what.str());
        }
    }
}

}  // namespace
}  // namespace whitted
