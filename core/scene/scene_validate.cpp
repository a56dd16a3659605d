// The semantic rules of SPEC §6 (validateScene, which the reader in
// scene_json_read.cpp applies too, so the editor and the loader refuse exactly
// the same scenes). Each field's rule comes from scene_fields.h.
#include <cmath>
#include <sstream>
#include <string_view>

#include "base/repeat_finder.h"
#include "scene/scene_io.h"
#include "scene/scene_json.h"

namespace whitted {

namespace {

using detail::quoted;

// Where a field is: its JSON path's start ("materials[2]", "camera") and, for
// an item of a list, which.
struct Place {
    std::string path;
    SceneList list = SceneList::None;
    std::size_t index = 0;
};

std::string indexed(const SceneField& list, std::size_t i) {
    return std::string(list.key) + "[" + std::to_string(i) + "]";
}

Place itemPlace(SceneList list, std::size_t i) {
    const SceneField& key = list == SceneList::Materials ? scene_field::kMaterials
                            : list == SceneList::Lights  ? scene_field::kLights
                                                         : scene_field::kSpheres;
    return {indexed(key, i), list, i};
}

std::string pathOf(const Place& place, const SceneField& f) {
    return place.path.empty() ? std::string(f.key) : place.path + "." + std::string(f.key);
}

SceneProblem problem(const Place& place, const SceneField& f, std::string reason,
                     ProblemKind kind = ProblemKind::BreaksRule) {
    return {pathOf(place, f), std::move(reason), kind, &f, place.list, place.index};
}

std::string number(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A vector field: Finite or Colour.
std::optional<SceneProblem> check(const Vec3& v, const SceneField& f, const Place& place) {
    if (!finite(v)) return problem(place, f, "must be finite", ProblemKind::NotFinite);
    if (f.rule == FieldRule::Colour && (v.x < 0 || v.y < 0 || v.z < 0))
        return problem(place, f, "colour components must be >= 0");
    return std::nullopt;
}

struct Bounds {
    double lo, hi;
    bool loOpen = false, hiOpen = false;
};

// A number field: each rule as an interval, said as the loader says it.
std::optional<SceneProblem> check(double v, const SceneField& f, const Place& place) {
    const auto atLeast = [&](bool open) -> std::optional<SceneProblem> {
        if (std::isfinite(v) && (open ? v > 0 : v >= 0)) return std::nullopt;
        return problem(place, f,
                       std::string(open ? "must be > 0" : "must be >= 0") + ", found " + number(v));
    };
    Bounds b{0, 1};
    switch (f.rule) {
        case FieldRule::Positive:
            return atLeast(true);
        case FieldRule::NonNegative:
            return atLeast(false);
        case FieldRule::UnitInterval:
            break;
        case FieldRule::ImageSize:
            b = {1, double(kMaxImageSize)};
            break;
        case FieldRule::Depth:
            b = {0, double(kMaxDepth)};
            break;
        case FieldRule::Samples:
            b = {1, double(kMaxSamplesPerPixel)};
            break;
        case FieldRule::FieldOfView:
            b = {0, 180, true, true};
            break;
        default:
            return std::nullopt;
    }
    if (std::isfinite(v) && (b.loOpen ? v > b.lo : v >= b.lo) && (b.hiOpen ? v < b.hi : v <= b.hi))
        return std::nullopt;
    return problem(place, f,
                   "must be in " + std::string(b.loOpen ? "(" : "[") + number(b.lo) + ", " +
                       number(b.hi) + (b.hiOpen ? ")" : "]") + ", found " + number(v));
}

template <typename T>
std::optional<SceneProblem> checkNames(const std::vector<T>& items, SceneList list) {
    // Paths built only for a problem: the editor validates every edit.
    RepeatFinder names(items.size(),
                       [&](std::size_t i) -> std::string_view { return items[i].name; });
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items[i].name.empty())
            return problem(itemPlace(list, i), scene_field::kName, "must not be empty",
                           ProblemKind::EmptyName);
        if (const auto earlier = names.add(i))
            return problem(itemPlace(list, i), scene_field::kName,
                           "duplicate name " + quoted(items[i].name) + " (also " +
                               itemPlace(list, *earlier).path + ")",
                           ProblemKind::RepeatedName);
    }
    return std::nullopt;
}

// The camera's basis: a view direction and an up vector not along it.
std::optional<SceneProblem> checkBasis(const Camera& c, const Place& camera) {
    const Vec3 forward = c.lookAt - c.position;
    if (forward == Vec3(0.0))
        return problem(camera, scene_field::kLookAt, "equals camera.position",
                       ProblemKind::LookAtIsPosition);
    if (c.up == Vec3(0.0))
        return problem(camera, scene_field::kUp, "must not be zero-length", ProblemKind::UpIsZero);
    // Exactly parallel only: a nearly parallel up still defines a basis, and
    // refusing it would make orbiting over the pole fail in the editor.
    const Vec3 f =
        forward / std::sqrt(forward.x * forward.x + forward.y * forward.y + forward.z * forward.z);
    const double upLen = std::sqrt(c.up.x * c.up.x + c.up.y * c.up.y + c.up.z * c.up.z);
    const Vec3 u = c.up / upLen;
    const Vec3 cr{u.y * f.z - u.z * f.y, u.z * f.x - u.x * f.z, u.x * f.y - u.y * f.x};
    if (cr.x * cr.x + cr.y * cr.y + cr.z * cr.z < 1e-24)
        return problem(camera, scene_field::kUp, "is parallel to the view direction",
                       ProblemKind::UpAlongView);
    return std::nullopt;
}

std::optional<SceneProblem> checkCamera(const Camera& c) {
    const Place camera{std::string(scene_field::kCamera.key)};
    if (auto p = check(c.position, scene_field::kCameraPosition, camera)) return p;
    if (auto p = check(c.lookAt, scene_field::kLookAt, camera)) return p;
    if (auto p = check(c.up, scene_field::kUp, camera)) return p;
    if (auto p = checkBasis(c, camera)) return p;
    return check(c.vfovDegrees, scene_field::kFieldOfView, camera);
}

std::optional<SceneProblem> checkRender(const RenderSettings& r) {
    const Place render{std::string(scene_field::kRender.key)};
    if (auto p = check(r.width, scene_field::kWidth, render)) return p;
    if (auto p = check(r.height, scene_field::kHeight, render)) return p;
    if (auto p = check(r.maxDepth, scene_field::kDepth, render)) return p;
    return check(r.samplesPerPixel, scene_field::kSamples, render);
}

std::optional<SceneProblem> checkLooks(const Scene& s) {
    if (auto p = check(s.background, scene_field::kBackground, {})) return p;
    return check(s.ambient, scene_field::kAmbient, {});
}

std::optional<SceneProblem> checkMaterial(const Material& m, std::size_t i) {
    const Place place = itemPlace(SceneList::Materials, i);
    if (auto e = check(m.diffuse, scene_field::kDiffuse, place)) return e;
    if (auto e = check(m.specular, scene_field::kSpecular, place)) return e;
    if (auto e = check(m.shininess, scene_field::kShininess, place)) return e;
    if (auto e = check(m.reflectivity, scene_field::kReflectivity, place)) return e;
    if (auto e = check(m.transparency, scene_field::kTransparency, place)) return e;
    if (auto e = check(m.ior, scene_field::kIor, place)) return e;
    if (!m.checker) return std::nullopt;
    const Place checker{pathOf(place, scene_field::kChecker), place.list, place.index};
    if (auto e = check(m.checker->color, scene_field::kCheckerColour, checker)) return e;
    return check(m.checker->size, scene_field::kCheckerSize, checker);
}

std::optional<SceneProblem> checkLight(const Light& l, std::size_t i) {
    const Place place = itemPlace(SceneList::Lights, i);
    if (auto p = check(l.position, scene_field::kLightPosition, place)) return p;
    if (auto p = check(l.color, scene_field::kLightColour, place)) return p;
    return check(l.intensity, scene_field::kIntensity, place);
}

bool sphereIsValid(const Sphere& s, bool materialFound) {
    return finite(s.center) && std::isfinite(s.radius) && s.radius > 0 && materialFound;
}

// Sphere `s` at place i of the scene's spheres (which may still hold another).
std::optional<SceneProblem> checkSphere(const Scene& scene, const Sphere& s, std::size_t i) {
    // The paths only for a problem: a selection of 100,000 spheres given a
    // material spent 30 ms of the edit building "spheres[i].center" strings.
    if (sphereIsValid(s, findMaterial(scene, s.material) >= 0)) return std::nullopt;
    const Place place = itemPlace(SceneList::Spheres, i);
    if (auto p = check(s.center, scene_field::kCentre, place)) return p;
    if (auto p = check(s.radius, scene_field::kRadius, place)) return p;
    return problem(place, scene_field::kSphereMaterial, "no material named " + quoted(s.material),
                   ProblemKind::UnknownMaterial);
}

// Same length and the same name at every index.
template <typename T>
bool sameNames(const std::vector<T>& a, const std::vector<T>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].name != b[i].name) return false;
    return true;
}

// The rules of the scene's own fields, in validateScene's order.
std::optional<SceneProblem> checkSceneFields(const Scene& s) {
    if (auto p = checkCamera(s.camera)) return p;
    if (auto p = checkRender(s.render)) return p;
    return checkLooks(s);
}

}  // namespace

std::optional<SceneProblem> validateScene(const Scene& scene) {
    if (auto p = checkSceneFields(scene)) return p;
    if (auto p = checkNames(scene.materials, SceneList::Materials)) return p;
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (auto p = checkMaterial(scene.materials[i], i)) return p;
    if (auto p = checkNames(scene.lights, SceneList::Lights)) return p;
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (auto p = checkLight(scene.lights[i], i)) return p;
    if (auto p = checkNames(scene.spheres, SceneList::Spheres)) return p;
    const auto materialNames = materialIndices(scene);
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        // The common case without building a path string: a file of a million
        // spheres checks every one.
        const Sphere& s = scene.spheres[i];
        if (sphereIsValid(s, materialNames.count(s.material) != 0)) continue;
        if (auto p = checkSphere(scene, s, i)) return p;
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
    if (auto p = checkSceneFields(after)) return p;
    for (std::size_t i = 0; i < after.materials.size(); ++i)
        if (!(before.materials[i] == after.materials[i]))
            if (auto p = checkMaterial(after.materials[i], i)) return p;
    for (std::size_t i = 0; i < after.lights.size(); ++i)
        if (!(before.lights[i] == after.lights[i]))
            if (auto p = checkLight(after.lights[i], i)) return p;
    for (std::size_t i = 0; i < after.spheres.size(); ++i)
        if (!(before.spheres[i] == after.spheres[i]))
            if (auto p = checkSphere(after, after.spheres[i], i)) return p;
    return std::nullopt;
}

// With every name unchanged and the scene before valid, only the changed item's
// own rules can fail, as validateEdit says.
std::optional<SceneProblem> validateSphereEdit(const Scene& scene, const Sphere& edited,
                                               std::size_t index) {
    return checkSphere(scene, edited, index);
}

std::optional<SceneProblem> validateLightEdit(const Light& edited, std::size_t index) {
    return checkLight(edited, index);
}

std::optional<SceneProblem> validateMaterialEdit(const Material& edited, std::size_t index) {
    return checkMaterial(edited, index);
}

std::optional<SceneProblem> validateSettingsEdit(const Scene& after) {
    return checkSceneFields(after);
}

}  // namespace whitted
