// The semantic rules of SPEC §6 (validateScene, which the reader in
// scene_json_read.cpp applies too, so the editor and the loader refuse exactly
// the same scenes) and the canonical writer.
#include "scene/scene_io.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string_view>
#include <system_error>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "base/repeat_finder.h"
#include "scene/scene_json.h"

namespace whitted {
namespace fs = std::filesystem;
using nlohmann::json;

SceneError::SceneError(std::string file, std::string jsonPath, std::string reason)
    : std::runtime_error(file + ": " + (jsonPath.empty() ? "" : jsonPath + ": ") + reason),
      file_(std::move(file)),
      path_(std::move(jsonPath)),
      reason_(std::move(reason)) {}

std::string detail::quoted(const std::string& s) {
    return json(s).dump();
}

namespace {

using detail::quoted;

// ---- semantic validation -------------------------------------------------

std::string indexed(const char* list, size_t i) {
    return std::string(list) + "[" + std::to_string(i) + "]";
}

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::optional<SceneProblem> checkVec(const Vec3& v, const std::string& path, bool colour) {
    if (!finite(v)) return SceneProblem{path, "must be finite"};
    if (colour && (v.x < 0 || v.y < 0 || v.z < 0))
        return SceneProblem{path, "colour components must be >= 0"};
    return std::nullopt;
}

std::optional<SceneProblem> checkRange(double v, double lo, double hi, const std::string& path,
                                       bool loOpen = false, bool hiOpen = false) {
    const bool ok = std::isfinite(v) && (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
    if (ok) return std::nullopt;
    auto fmt = [](double x) {
        std::ostringstream s;
        s << x;
        return s.str();
    };
    return SceneProblem{path, "must be in " + std::string(loOpen ? "(" : "[") + fmt(lo) + ", " +
                                  fmt(hi) + (hiOpen ? ")" : "]") + ", found " + fmt(v)};
}

std::optional<SceneProblem> checkAtLeast(double v, double lo, const std::string& path, bool open) {
    if (std::isfinite(v) && (open ? v > lo : v >= lo)) return std::nullopt;
    std::ostringstream s;
    s << "must be " << (open ? "> " : ">= ") << lo << ", found " << v;
    return SceneProblem{path, s.str()};
}

template <typename T>
std::optional<SceneProblem> checkNames(const std::vector<T>& items, const char* list) {
    // Paths built only for a problem: the editor validates every edit.
    RepeatFinder names(items.size(),
                       [&](std::size_t i) -> std::string_view { return items[i].name; });
    for (size_t i = 0; i < items.size(); ++i) {
        if (items[i].name.empty())
            return SceneProblem{indexed(list, i) + ".name", "must not be empty"};
        if (const auto earlier = names.add(i))
            return SceneProblem{indexed(list, i) + ".name", "duplicate name " +
                                                                quoted(items[i].name) + " (also " +
                                                                indexed(list, *earlier) + ")"};
    }
    return std::nullopt;
}

std::optional<SceneProblem> checkCamera(const Camera& c) {
    if (auto p = checkVec(c.position, "camera.position", false)) return p;
    if (auto p = checkVec(c.lookAt, "camera.look_at", false)) return p;
    if (auto p = checkVec(c.up, "camera.up", false)) return p;
    const Vec3 forward = c.lookAt - c.position;
    if (forward == Vec3(0.0)) return SceneProblem{"camera.look_at", "equals camera.position"};
    if (c.up == Vec3(0.0)) return SceneProblem{"camera.up", "must not be zero-length"};
    // Exactly parallel only: a nearly parallel up still defines a basis, and
    // refusing it would make orbiting over the pole fail in the editor.
    const Vec3 f =
        forward / std::sqrt(forward.x * forward.x + forward.y * forward.y + forward.z * forward.z);
    const double upLen = std::sqrt(c.up.x * c.up.x + c.up.y * c.up.y + c.up.z * c.up.z);
    const Vec3 u = c.up / upLen;
    const Vec3 cr{u.y * f.z - u.z * f.y, u.z * f.x - u.x * f.z, u.x * f.y - u.y * f.x};
    if (cr.x * cr.x + cr.y * cr.y + cr.z * cr.z < 1e-24)
        return SceneProblem{"camera.up", "is parallel to the view direction"};
    return checkRange(c.vfovDegrees, 0, 180, "camera.vfov_degrees", true, true);
}

std::optional<SceneProblem> checkRender(const RenderSettings& r) {
    if (auto p = checkRange(r.width, 1, kMaxImageSize, "render.width")) return p;
    if (auto p = checkRange(r.height, 1, kMaxImageSize, "render.height")) return p;
    if (auto p = checkRange(r.maxDepth, 0, kMaxDepth, "render.max_depth")) return p;
    return checkRange(r.samplesPerPixel, 1, kMaxSamplesPerPixel, "render.samples_per_pixel");
}

std::optional<SceneProblem> checkMaterial(const Material& m, const std::string& p) {
    if (auto e = checkVec(m.diffuse, p + ".diffuse", true)) return e;
    if (auto e = checkAtLeast(m.specular, 0, p + ".specular", false)) return e;
    if (auto e = checkAtLeast(m.shininess, 0, p + ".shininess", false)) return e;
    if (auto e = checkRange(m.reflectivity, 0, 1, p + ".reflectivity")) return e;
    if (auto e = checkRange(m.transparency, 0, 1, p + ".transparency")) return e;
    if (auto e = checkAtLeast(m.ior, 0, p + ".ior", true)) return e;
    if (m.checker) {
        if (auto e = checkVec(m.checker->color, p + ".checker.color", true)) return e;
        if (auto e = checkAtLeast(m.checker->size, 0, p + ".checker.size", true)) return e;
    }
    return std::nullopt;
}

std::optional<SceneProblem> checkLight(const Light& l, size_t i) {
    const std::string path = indexed("lights", i);
    if (auto p = checkVec(l.position, path + ".position", false)) return p;
    if (auto p = checkVec(l.color, path + ".color", true)) return p;
    return checkAtLeast(l.intensity, 0, path + ".intensity", false);
}

bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::optional<SceneProblem> checkSphere(const Scene& scene, size_t i) {
    const Sphere& s = scene.spheres[i];
    // The paths only for a problem: a selection of 100,000 spheres given a
    // material spent 30 ms of the edit building "spheres[i].center" strings.
    if (finite(s.center) && std::isfinite(s.radius) && s.radius > 0 &&
        findMaterial(scene, s.material) >= 0)
        return std::nullopt;
    const std::string path = indexed("spheres", i);
    if (auto p = checkVec(s.center, path + ".center", false)) return p;
    if (auto p = checkAtLeast(s.radius, 0, path + ".radius", true)) return p;
    if (findMaterial(scene, s.material) < 0)
        return SceneProblem{path + ".material", "no material named " + quoted(s.material)};
    return std::nullopt;
}

// Same length and the same name at every index.
template <typename T>
bool sameNames(const std::vector<T>& a, const std::vector<T>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].name != b[i].name) return false;
    return true;
}

}  // namespace

std::optional<SceneProblem> validateScene(const Scene& scene) {
    if (auto p = checkCamera(scene.camera)) return p;
    if (auto p = checkRender(scene.render)) return p;
    if (auto p = checkVec(scene.background, "background", true)) return p;
    if (auto p = checkVec(scene.ambient, "ambient", true)) return p;
    if (auto p = checkNames(scene.materials, "materials")) return p;
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (auto p = checkMaterial(scene.materials[i], indexed("materials", i))) return p;
    if (auto p = checkNames(scene.lights, "lights")) return p;
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (auto p = checkLight(scene.lights[i], i)) return p;
    if (auto p = checkNames(scene.spheres, "spheres")) return p;
    const auto materialNames = materialIndices(scene);
    for (size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        // The common case without building a path string: a file of a million
        // spheres checks every one.
        if (isFinite(s.center) && std::isfinite(s.radius) && s.radius > 0 &&
            materialNames.count(s.material))
            continue;
        if (auto p = checkSphere(scene, i)) return p;
    }
    return std::nullopt;
}

// Names are the only rule between items (a sphere's material is looked up by
// name among the materials); with every list's names unchanged and `before`
// valid, a changed value can break only its own item's rules, checked here in
// validateScene's order, so the first problem is the one it would report.
std::optional<SceneProblem> validateEdit(const Scene& before, const Scene& after) {
    if (!sameNames(before.materials, after.materials) || !sameNames(before.lights, after.lights) ||
        !sameNames(before.spheres, after.spheres))
        return validateScene(after);
    if (auto p = checkCamera(after.camera)) return p;
    if (auto p = checkRender(after.render)) return p;
    if (auto p = checkVec(after.background, "background", true)) return p;
    if (auto p = checkVec(after.ambient, "ambient", true)) return p;
    for (size_t i = 0; i < after.materials.size(); ++i)
        if (!(before.materials[i] == after.materials[i]))
            if (auto p = checkMaterial(after.materials[i], indexed("materials", i))) return p;
    for (size_t i = 0; i < after.lights.size(); ++i)
        if (!(before.lights[i] == after.lights[i]))
            if (auto p = checkLight(after.lights[i], i)) return p;
    for (size_t i = 0; i < after.spheres.size(); ++i)
        if (!(before.spheres[i] == after.spheres[i]))
            if (auto p = checkSphere(after, i)) return p;
    return std::nullopt;
}

// With every name unchanged and the scene before valid, only the changed item's
// own rules can fail, as validateEdit says.
std::optional<SceneProblem> validateSphereEdit(const Scene& after, size_t index) {
    return checkSphere(after, index);
}

std::optional<SceneProblem> validateLightEdit(const Scene& after, size_t index) {
    return checkLight(after.lights[index], index);
}

std::optional<SceneProblem> validateMaterialEdit(const Scene& after, size_t index) {
    return checkMaterial(after.materials[index], indexed("materials", index));
}

// ---- canonical writer ------------------------------------------------------

namespace {

// Integral values print without a fraction ("1", not "1.0") so hand-written
// scenes and saved ones look alike; others use nlohmann's shortest round-trip form.
std::string num(double v) {
    if (v == std::floor(v) && std::fabs(v) < 9.0e15) {
        return std::to_string(static_cast<long long>(v));
    }
    return json(v).dump();
}

// Built by appending: GCC 12 warns falsely (-Wrestrict, bug 105329) on
// "literal" + std::string chains at -O3.
std::string vec(const Vec3& v) {
    std::string out = "[";
    out.append(num(v.x)).append(", ").append(num(v.y)).append(", ").append(num(v.z));
    return out.append("]");
}

using Fields = detail::JsonFields;

std::string object(const Fields& fields) {
    std::string out = "{";
    for (size_t i = 0; i < fields.size(); ++i) {
        if (i) out += ", ";
        out.append("\"").append(fields[i].first).append("\": ").append(fields[i].second);
    }
    return out + "}";
}

}  // namespace

std::string detail::jsonItem(const Material& m) {
    Fields f = {{"name", quoted(m.name)},
                {"diffuse", vec(m.diffuse)},
                {"specular", num(m.specular)},
                {"shininess", num(m.shininess)},
                {"reflectivity", num(m.reflectivity)},
                {"transparency", num(m.transparency)},
                {"ior", num(m.ior)}};
    if (m.checker)
        f.push_back({"checker",
                     object({{"color", vec(m.checker->color)}, {"size", num(m.checker->size)}})});
    return object(f);
}

std::string detail::jsonItem(const Light& l) {
    return object({{"name", quoted(l.name)},
                   {"position", vec(l.position)},
                   {"color", vec(l.color)},
                   {"intensity", num(l.intensity)}});
}

std::string detail::jsonItem(const Sphere& s) {
    return object({{"name", quoted(s.name)},
                   {"center", vec(s.center)},
                   {"radius", num(s.radius)},
                   {"material", quoted(s.material)}});
}

std::string detail::jsonDocument(const JsonFields& top) {
    std::string out = "{\n";
    for (size_t i = 0; i < top.size(); ++i)
        out.append("  \"")
            .append(top[i].first)
            .append("\": ")
            .append(top[i].second)
            .append(i + 1 < top.size() ? ",\n" : "\n");
    return out + "}\n";
}

std::string sceneToJson(const Scene& s) {
    using detail::jsonList;
    const Camera& c = s.camera;
    const RenderSettings& r = s.render;
    return detail::jsonDocument({
        {"format", quoted("whitted-scene")},
        {"version", num(kSceneFormatVersion)},
        {"camera", object({{"position", vec(c.position)},
                           {"look_at", vec(c.lookAt)},
                           {"up", vec(c.up)},
                           {"vfov_degrees", num(c.vfovDegrees)}})},
        {"render", object({{"width", num(r.width)},
                           {"height", num(r.height)},
                           {"max_depth", num(r.maxDepth)},
                           {"samples_per_pixel", num(r.samplesPerPixel)},
                           {"precision", quoted(std::string(precisionName(r.precision)))}})},
        {"background", vec(s.background)},
        {"ambient", vec(s.ambient)},
        {"materials", jsonList(s.materials)},
        {"lights", jsonList(s.lights)},
        {"spheres", jsonList(s.spheres)},
    });
}

std::string sceneContentDigest(const Scene& scene) {
    Scene content = scene;
    content.render = RenderSettings{};
    std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a's offset basis and prime
    for (const unsigned char byte : sceneToJson(content)) hash = (hash ^ byte) * 0x100000001b3ull;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

void saveScene(const Scene& scene, const fs::path& file) {
    replaceFileWithText(file, sceneToJson(scene));
}

}  // namespace whitted
