// The canonical writer, and what the readers and the validator
// (scene_validate.cpp) share: SceneError and quoting a name.
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
    using namespace scene_field;
    Fields f = {{kName.key, quoted(m.name)},
                {kDiffuse.key, vec(m.diffuse)},
                {kSpecular.key, num(m.specular)},
                {kShininess.key, num(m.shininess)},
                {kReflectivity.key, num(m.reflectivity)},
                {kTransparency.key, num(m.transparency)},
                {kIor.key, num(m.ior)}};
    if (m.checker)
        f.push_back({kChecker.key, object({{kCheckerColour.key, vec(m.checker->color)},
                                           {kCheckerSize.key, num(m.checker->size)}})});
    return object(f);
}

std::string detail::jsonItem(const Light& l) {
    using namespace scene_field;
    return object({{kName.key, quoted(l.name)},
                   {kLightPosition.key, vec(l.position)},
                   {kLightColour.key, vec(l.color)},
                   {kIntensity.key, num(l.intensity)}});
}

std::string detail::jsonItem(const Sphere& s) {
    using namespace scene_field;
    return object({{kName.key, quoted(s.name)},
                   {kCentre.key, vec(s.center)},
                   {kRadius.key, num(s.radius)},
                   {kSphereMaterial.key, quoted(s.material)}});
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
    using namespace scene_field;
    const Camera& c = s.camera;
    const RenderSettings& r = s.render;
    return detail::jsonDocument({
        {kFormat.key, detail::quoted(std::string(kSceneFormatName))},
        {kVersion.key, num(kSceneFormatVersion)},
        {kCamera.key, object({{kCameraPosition.key, vec(c.position)},
                              {kLookAt.key, vec(c.lookAt)},
                              {kUp.key, vec(c.up)},
                              {kFieldOfView.key, num(c.vfovDegrees)}})},
        {kRender.key,
         object({{kWidth.key, num(r.width)},
                 {kHeight.key, num(r.height)},
                 {kDepth.key, num(r.maxDepth)},
                 {kSamples.key, num(r.samplesPerPixel)},
                 {kPrecision.key, detail::quoted(std::string(precisionName(r.precision)))}})},
        {kBackground.key, vec(s.background)},
        {kAmbient.key, vec(s.ambient)},
        {kMaterials.key, jsonList(s.materials)},
        {kLights.key, jsonList(s.lights)},
        {kSpheres.key, jsonList(s.spheres)},
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
