// The scene model: plain value types mirroring the JSON scene file (SPEC §6).
//
// Everything is stored in double so that a file's numbers survive load and save
// unchanged; the tracer converts to its working precision when a render starts.
// Spheres name their material; the tracer resolves names to indices once per render.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

namespace whitted {

using Vec3 = glm::dvec3;  // positions (scene units) and linear RGB colours

struct Checker {
    Vec3 color{0.0, 0.0, 0.0};
    double size = 1.0;  // edge length of one checker cell, scene units, > 0
    bool operator==(const Checker&) const = default;
};

struct Material {
    std::string name;
    Vec3 diffuse{0.8, 0.8, 0.8};
    double specular = 0.0;      // ks
    double shininess = 50.0;    // Phong exponent n of the Blinn half-vector term
    double reflectivity = 0.0;  // kr in [0,1]
    double transparency = 0.0;  // kt in [0,1]; also the shadow transmittance
    double ior = 1.5;           // index of refraction, > 0; the outside medium is 1
    std::optional<Checker> checker;
    bool operator==(const Material&) const = default;
};

struct Light {
    std::string name;
    Vec3 position{0.0, 0.0, 0.0};
    Vec3 color{1.0, 1.0, 1.0};
    double intensity = 1.0;  // c_j = color * intensity; no fall-off with distance
    bool operator==(const Light&) const = default;
};

struct Sphere {
    std::string name;
    Vec3 center{0.0, 0.0, 0.0};
    double radius = 1.0;  // > 0
    std::string material;
    bool operator==(const Sphere&) const = default;
};

struct Camera {
    Vec3 position{0.0, 0.0, -1.0};
    Vec3 lookAt{0.0, 0.0, 0.0};  // also the editor's orbit centre
    Vec3 up{0.0, 1.0, 0.0};
    double vfovDegrees = 60.0;  // vertical field of view, in (0, 180)
    bool operator==(const Camera&) const = default;
};

enum class Precision { Float, Double };

// The one table behind the file format, the CLI and any combo box.
inline constexpr std::array<std::pair<Precision, std::string_view>, 2> kPrecisionNames{{
    {Precision::Float, "float"},
    {Precision::Double, "double"},
}};
std::string_view precisionName(Precision p);
std::optional<Precision> parsePrecision(std::string_view name);

struct RenderSettings {
    int width = 640;          // [1, 16384]
    int height = 480;         // [1, 16384]
    int maxDepth = 5;         // [0, 64]; camera rays have depth 0
    int samplesPerPixel = 1;  // [1, 65536]
    Precision precision = Precision::Float;
    bool operator==(const RenderSettings&) const = default;
};

struct Scene {
    Camera camera;
    RenderSettings render;
    Vec3 background{0.0, 0.0, 0.0};
    Vec3 ambient{0.05, 0.05, 0.05};
    std::vector<Material> materials;
    std::vector<Light> lights;
    std::vector<Sphere> spheres;
    bool operator==(const Scene&) const = default;
};

// Limits shared by the loader, the CLI and the editor's spin boxes.
inline constexpr int kMaxImageSize = 16384;
inline constexpr int kMaxDepth = 64;
inline constexpr int kMaxSamplesPerPixel = 65536;

// Whether two scenes differ at most in their render settings.
bool sameSceneContent(const Scene& a, const Scene& b);

// Index of the named material, or -1.
int findMaterial(const Scene& scene, std::string_view name);

// Each material's index by its name (the first of equal names, as
// findMaterial), for looking up the materials of many spheres: one hash each
// instead of a comparison per material. The views point into `scene`.
std::unordered_map<std::string_view, int> materialIndices(const Scene& scene);

}  // namespace whitted
