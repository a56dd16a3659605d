// Helpers over the core's types, one copy for the core, app and GUI tests: the
// seed scene loaded (at a size) or saved for a test to open, scenes built a
// line at a time, a material preset by name, and images rendered in one pass
// and compared bit for bit, and rows traced from two preparations of a scene
// compared likewise.
#pragma once

#include <cmath>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "image/image.h"
#include "scene/material_presets.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "support/test_support.h"
#include "tracer/kernel_dispatch.h"
#include "tracer/renderer.h"
#include "tracer/tracer.h"

namespace whitted::test {

// ---- the seed scene -----------------------------------------------------------

// scenes/seed.json as it is.
inline Scene seedScene() {
    return loadScene(kSeedScenePath);
}

// scenes/seed.json at the given size.
inline Scene seedScene(int width, int height) {
    Scene s = seedScene();
    s.render.width = width;
    s.render.height = height;
    return s;
}

// scenes/seed.json at the given size and precision.
inline Scene seedScene(int width, int height, Precision precision) {
    Scene s = seedScene(width, height);
    s.render.precision = precision;
    return s;
}

// `scene` saved as `name` in `dir`, for a test to open; the file's path.
inline std::string saveSceneIn(const TempDir& dir, const Scene& scene,
                               const std::string& name = "seed.json") {
    const std::string path = (dir / name).string();
    saveScene(scene, path);
    return path;
}

// ---- scenes a line at a time --------------------------------------------------

inline Material makeMaterial(const std::string& name, Vec3 diffuse, double specular = 0,
                             double reflectivity = 0, double transparency = 0, double ior = 1.5) {
    Material m;
    m.name = name;
    m.diffuse = diffuse;
    m.specular = specular;
    m.reflectivity = reflectivity;
    m.transparency = transparency;
    m.ior = ior;
    return m;
}

inline Sphere makeSphere(const std::string& name, Vec3 centre, double radius,
                         const std::string& material) {
    Sphere s;
    s.name = name;
    s.center = centre;
    s.radius = radius;
    s.material = material;
    return s;
}

inline Light makeLight(const std::string& name, Vec3 position, Vec3 colour = {1, 1, 1},
                       double intensity = 1) {
    Light l;
    l.name = name;
    l.position = position;
    l.color = colour;
    l.intensity = intensity;
    return l;
}

// A 1x1 image from a camera at `from` looking at `at` (up +y, 60 degrees), black
// background, no ambient: with the defaults the only ray is the centre ray,
// exactly (0,0,1).
inline Scene centreRayScene(Precision precision, Vec3 from = {0, 0, 0}, Vec3 at = {0, 0, 1}) {
    Scene s;
    s.camera.position = from;
    s.camera.lookAt = at;
    s.camera.up = {0, 1, 0};
    s.camera.vfovDegrees = 60;
    s.render.width = s.render.height = 1;
    s.render.maxDepth = 5;
    s.render.samplesPerPixel = 1;
    s.render.precision = precision;
    s.background = {0, 0, 0};
    s.ambient = {0, 0, 0};
    return s;
}

// A hand-computed pixel: 1e-5 relative plus 1e-7 absolute (for values near
// zero), in both precisions; the image stores float, and a float render loses a
// few ulps (1.2e-7 each) per operation.
inline void expectColour(const Vec3& actual, const Vec3& expected, const std::string& what) {
    constexpr double kRelTol = 1e-5, kAbsTol = 1e-7;
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], kRelTol * std::fabs(expected[c]) + kAbsTol)
            << what << ", channel " << c;
}

// The material preset of that name (scene/material_presets.h).
inline const MaterialPreset& preset(std::string_view name) {
    for (const MaterialPreset& p : materialPresets())
        if (p.name == name) return p;
    ADD_FAILURE() << "no preset " << name;
    return materialPresets().front();
}

// ---- images -------------------------------------------------------------------

// The image of one render of `scene`, all samples at once (not progressive).
inline Image renderImage(const Scene& scene) {
    RenderOptions o;
    o.progressive = false;
    return render(scene, o).image;
}

// The same size and the same bits in every channel.
inline bool samePixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
           std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

// Where two images first differ, for a readable failure; "" when samePixels.
inline std::string firstDifference(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        return "sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
               " vs " + std::to_string(b.width) + "x" + std::to_string(b.height);
    for (std::size_t k = 0; k < a.rgb.size(); ++k)
        if (std::memcmp(&a.rgb[k], &b.rgb[k], sizeof(float)) != 0) {
            const std::size_t p = k / 3;
            return "pixel (" + std::to_string(p % a.width) + ", " + std::to_string(p / a.width) +
                   ") channel " + std::to_string(k % 3) + ": " + std::to_string(a.rgb[k]) + " vs " +
                   std::to_string(b.rgb[k]);
        }
    return "";
}

// ---- kernels -------------------------------------------------------------------

// Runs check(kernel) under each kernel this CPU runs (kernel_dispatch.h), its
// failures traced with the kernel's name, then goes back to the kernel chosen
// at start, so that the tests after it run under that one.
template <typename Check>
void forEveryKernel(const Check& check) {
    for (const std::string& kernel : supportedKernelNames()) {
        SCOPED_TRACE("kernel " + kernel);
        useKernel(kernel);
        check(kernel);
    }
    useKernel("");
}

// ---- rows traced ---------------------------------------------------------------

// Every row of every sample of `scene`, traced from two preparations of it
// (one with a shortcut, one without): equal bit for bit, pixel by pixel, with
// as many rays.
template <typename T>
void expectSameRows(const PreparedScene<T>& a, const PreparedScene<T>& b, const Scene& scene,
                    const std::string& what) {
    const int w = scene.render.width;
    for (int y = 0; y < scene.render.height; ++y)
        for (int n = 0; n < scene.render.samplesPerPixel; ++n) {
            std::vector<Vec<T>> rowA(w), rowB(w);
            RayCounts countsA, countsB;
            traceCameraRow(a, y, 0, w, n, rowA.data(), countsA);
            traceCameraRow(b, y, 0, w, n, rowB.data(), countsB);
            for (int x = 0; x < w; ++x)
                EXPECT_EQ(rowA[x], rowB[x])
                    << what << " pixel " << x << "," << y << " sample " << n;
            EXPECT_EQ(countsA.total(), countsB.total()) << what << " row " << y;
        }
}

}  // namespace whitted::test
