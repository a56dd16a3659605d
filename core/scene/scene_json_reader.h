// The scene file's DOM reader: one JSON value to Scene structs, checking
// structure (keys, types, finiteness) with the JSON path of every refusal.
// The streaming parser (scene_json_read.cpp) hands it the small top-level
// DOM and each list element alone; only that parser and the clipboard's
// (scene_fragment.cpp), which reads its items as a file's, include this one.
#pragma once

#include <cmath>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_io.h"
#include "scene/scene_json.h"

namespace whitted::detail {

using nlohmann::json;

inline std::string typeName(const json& j) {
    if (j.is_number()) return "a number";
    if (j.is_string()) return "a string";
    if (j.is_boolean()) return "a boolean";
    if (j.is_array()) return "an array";
    if (j.is_object()) return "an object";
    return "null";
}

inline std::string joinKey(const std::string& parent, std::string_view key) {
    return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

// A top-level list read element by element: the elements read so far and
// the first refusal among them (later elements are still parsed, for syntax).
template <typename T>
struct Streamed {
    std::vector<T> items;
    std::optional<SceneError> error;
};

struct Lists {
    std::uintmax_t textBytes = 0;  // the whole text's, for an estimate of the sphere count
    Streamed<Material> materials;
    Streamed<Light> lights;
    Streamed<Sphere> spheres;
};

// Reads one JSON document into a Scene; every failure names the JSON path.
class Reader {
  public:
    explicit Reader(std::string file) : file_(std::move(file)) {}
    const std::string& file() const { return file_; }

    [[noreturn]] void fail(const std::string& path, const std::string& reason) const {
        throw SceneError(file_, path, reason);
    }

    void expectObject(const json& j, const std::string& path) const {
        if (!j.is_object()) fail(path, "expected an object, found " + typeName(j));
    }

    void expectArray(const json& j, const std::string& path) const {
        if (!j.is_array()) fail(path, "expected an array, found " + typeName(j));
    }

    void checkKeys(const json& obj, const std::string& path,
                   std::initializer_list<SceneField> allowed) const {
        for (auto it = obj.begin(); it != obj.end(); ++it) {
            bool known = false;
            for (const SceneField& a : allowed) known = known || it.key() == a.key;
            if (!known) fail(joinKey(path, it.key()), "unknown key");
        }
    }

    const json* find(const json& obj, const std::string& path, const SceneField& f,
                     bool required) const {
        auto it = obj.find(f.key);
        if (it == obj.end()) {
            if (required) fail(joinKey(path, f.key), "missing");
            return nullptr;
        }
        return &*it;
    }

    double number(const json& j, const std::string& path) const {
        if (!j.is_number()) fail(path, "expected a number, found " + typeName(j));
        const double v = j.get<double>();
        if (!std::isfinite(v)) fail(path, "must be a finite number");
        return v;
    }

    int integer(const json& j, const std::string& path) const {
        const double v = number(j, path);
        if (v != std::floor(v) || std::fabs(v) > 2e9) fail(path, "must be an integer");
        return static_cast<int>(v);
    }

    std::string string(const json& j, const std::string& path) const {
        if (!j.is_string()) fail(path, "expected a string, found " + typeName(j));
        return j.get<std::string>();
    }

    Vec3 vec3(const json& j, const std::string& path) const {
        if (!j.is_array() || j.size() != 3)
            fail(path,
                 "expected an array of 3 numbers, found " +
                     (j.is_array() ? "an array of " + std::to_string(j.size()) : typeName(j)));
        Vec3 v;
        for (int i = 0; i < 3; ++i) v[i] = number(j[i], path + "[" + std::to_string(i) + "]");
        return v;
    }

    // Optional fields keep `out` as it is (the default) when absent.
    void opt(const json& obj, const std::string& path, const SceneField& f, double& out) const {
        if (auto* j = find(obj, path, f, false)) out = number(*j, joinKey(path, f.key));
    }
    void opt(const json& obj, const std::string& path, const SceneField& f, int& out) const {
        if (auto* j = find(obj, path, f, false)) out = integer(*j, joinKey(path, f.key));
    }
    void opt(const json& obj, const std::string& path, const SceneField& f, Vec3& out) const {
        if (auto* j = find(obj, path, f, false)) out = vec3(*j, joinKey(path, f.key));
    }
    template <typename T>
    void req(const json& obj, const std::string& path, const SceneField& f, T& out) const {
        find(obj, path, f, true);
        opt(obj, path, f, out);
    }
    void reqName(const json& obj, const std::string& path, std::string& out) const {
        out = string(*find(obj, path, scene_field::kName, true),
                     joinKey(path, scene_field::kName.key));
    }

    // `root` holds an empty array in place of each list that was streamed into `lists`.
    Scene read(const json& root, Lists& lists) const {
        using namespace scene_field;
        expectObject(root, "");
        checkKeys(root, "",
                  {kFormat, kVersion, kCamera, kRender, kBackground, kAmbient, kMaterials, kLights,
                   kSpheres});
        const json* format = find(root, "", kFormat, true);
        if (!format->is_string() || format->get<std::string>() != kSceneFormatName)
            fail("format", "expected \"whitted-scene\", found " + format->dump());
        readVersion(root, kSceneFormatVersion);

        Scene scene;
        readCamera(*find(root, "", kCamera, true), scene.camera);
        if (auto* r = find(root, "", kRender, false)) readRender(*r, scene.render);
        opt(root, "", kBackground, scene.background);
        opt(root, "", kAmbient, scene.ambient);
        take(root, kMaterials, lists.materials, scene.materials);
        take(root, kLights, lists.lights, scene.lights);
        take(root, kSpheres, lists.spheres, scene.spheres);
        return scene;
    }

    // A document's "version", no newer than `newest`.
    void readVersion(const json& root, int newest) const {
        const int version = integer(*find(root, "", scene_field::kVersion, true), "version");
        if (version > newest)
            fail("version", std::to_string(version) + " is newer than this program reads (" +
                                std::to_string(newest) + ")");
        if (version < 1) fail("version", "must be at least 1");
    }

    // The reading of one list element: its value, its JSON path, its struct.
    template <typename T>
    using ReadOne = void (Reader::*)(const json&, const std::string&, T&) const;

    // The list's elements were read as they streamed past; its first bad
    // element is reported here, where reading the whole DOM reported it.
    template <typename T>
    void take(const json& root, const SceneField& list, Streamed<T>& streamed,
              std::vector<T>& out) const {
        const json* j = find(root, "", list, false);
        if (!j) return;
        expectArray(*j, std::string(list.key));
        if (streamed.error) throw *streamed.error;
        out = std::move(streamed.items);
    }

    void readCamera(const json& j, Camera& c) const {
        using namespace scene_field;
        const std::string p(kCamera.key);
        expectObject(j, p);
        checkKeys(j, p, {kCameraPosition, kLookAt, kUp, kFieldOfView});
        req(j, p, kCameraPosition, c.position);
        req(j, p, kLookAt, c.lookAt);
        opt(j, p, kUp, c.up);
        opt(j, p, kFieldOfView, c.vfovDegrees);
    }

    void readRender(const json& j, RenderSettings& r) const {
        using namespace scene_field;
        const std::string p(kRender.key);
        expectObject(j, p);
        checkKeys(j, p, {kWidth, kHeight, kDepth, kSamples, kPrecision});
        opt(j, p, kWidth, r.width);
        opt(j, p, kHeight, r.height);
        opt(j, p, kDepth, r.maxDepth);
        opt(j, p, kSamples, r.samplesPerPixel);
        if (auto* pr = find(j, p, kPrecision, false)) {
            const std::string path = joinKey(p, kPrecision.key);
            const std::string name = string(*pr, path);
            auto parsed = parsePrecision(name);
            if (!parsed) fail(path, "expected \"float\" or \"double\", found " + quoted(name));
            r.precision = *parsed;
        }
    }

    void readMaterial(const json& j, const std::string& p, Material& m) const {
        using namespace scene_field;
        expectObject(j, p);
        checkKeys(
            j, p,
            {kName, kDiffuse, kSpecular, kShininess, kReflectivity, kTransparency, kIor, kChecker});
        reqName(j, p, m.name);
        opt(j, p, kDiffuse, m.diffuse);
        opt(j, p, kSpecular, m.specular);
        opt(j, p, kShininess, m.shininess);
        opt(j, p, kReflectivity, m.reflectivity);
        opt(j, p, kTransparency, m.transparency);
        opt(j, p, kIor, m.ior);
        if (auto* c = find(j, p, kChecker, false)) {
            const std::string cp = joinKey(p, kChecker.key);
            expectObject(*c, cp);
            checkKeys(*c, cp, {kCheckerColour, kCheckerSize});
            Checker checker;
            req(*c, cp, kCheckerColour, checker.color);
            req(*c, cp, kCheckerSize, checker.size);
            m.checker = checker;
        }
    }

    void readLight(const json& j, const std::string& p, Light& l) const {
        using namespace scene_field;
        expectObject(j, p);
        checkKeys(j, p, {kName, kLightPosition, kLightColour, kIntensity});
        reqName(j, p, l.name);
        req(j, p, kLightPosition, l.position);
        opt(j, p, kLightColour, l.color);
        opt(j, p, kIntensity, l.intensity);
    }

    void readSphere(const json& j, const std::string& p, Sphere& s) const {
        using namespace scene_field;
        expectObject(j, p);
        checkKeys(j, p, {kName, kCentre, kRadius, kSphereMaterial});
        reqName(j, p, s.name);
        req(j, p, kCentre, s.center);
        req(j, p, kRadius, s.radius);
        s.material = string(*find(j, p, kSphereMaterial, true), joinKey(p, kSphereMaterial.key));
    }

  private:
    std::string file_;
};

// The text's JSON syntax checked whole, its top-level values as a DOM (the
// return value) and the elements of its top-level "materials", "lights" and
// "spheres" read into `lists`, as parseScene reads a file; Reader::read or
// Reader::take then reports the lists' first refusal. Throws SceneError for
// bad syntax, naming reader.file().
json parseTopLevel(const std::string& text, const Reader& reader, Lists& lists);

}  // namespace whitted::detail
