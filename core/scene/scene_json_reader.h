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

inline std::string joinKey(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
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
                   std::initializer_list<std::string_view> allowed) const {
        for (auto it = obj.begin(); it != obj.end(); ++it) {
            bool known = false;
            for (auto a : allowed) known = known || it.key() == a;
            if (!known) fail(joinKey(path, it.key()), "unknown key");
        }
    }

    const json* find(const json& obj, const std::string& path, const char* key,
                     bool required) const {
        auto it = obj.find(key);
        if (it == obj.end()) {
            if (required) fail(joinKey(path, key), "missing");
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
    void opt(const json& obj, const std::string& path, const char* key, double& out) const {
        if (auto* j = find(obj, path, key, false)) out = number(*j, joinKey(path, key));
    }
    void opt(const json& obj, const std::string& path, const char* key, int& out) const {
        if (auto* j = find(obj, path, key, false)) out = integer(*j, joinKey(path, key));
    }
    void opt(const json& obj, const std::string& path, const char* key, Vec3& out) const {
        if (auto* j = find(obj, path, key, false)) out = vec3(*j, joinKey(path, key));
    }
    template <typename T>
    void req(const json& obj, const std::string& path, const char* key, T& out) const {
        find(obj, path, key, true);
        opt(obj, path, key, out);
    }
    void reqName(const json& obj, const std::string& path, std::string& out) const {
        out = string(*find(obj, path, "name", true), joinKey(path, "name"));
    }

    // `root` holds an empty array in place of each list that was streamed into `lists`.
    Scene read(const json& root, Lists& lists) const {
        expectObject(root, "");
        checkKeys(root, "",
                  {"format", "version", "camera", "render", "background", "ambient", "materials",
                   "lights", "spheres"});
        const json* format = find(root, "", "format", true);
        if (!format->is_string() || format->get<std::string>() != "whitted-scene")
            fail("format", "expected \"whitted-scene\", found " + format->dump());
        readVersion(root, kSceneFormatVersion);

        Scene scene;
        readCamera(*find(root, "", "camera", true), scene.camera);
        if (auto* r = find(root, "", "render", false)) readRender(*r, scene.render);
        opt(root, "", "background", scene.background);
        opt(root, "", "ambient", scene.ambient);
        take(root, "materials", lists.materials, scene.materials);
        take(root, "lights", lists.lights, scene.lights);
        take(root, "spheres", lists.spheres, scene.spheres);
        return scene;
    }

    // A document's "version", no newer than `newest`.
    void readVersion(const json& root, int newest) const {
        const int version = integer(*find(root, "", "version", true), "version");
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
    void take(const json& root, const char* key, Streamed<T>& list, std::vector<T>& out) const {
        const json* j = find(root, "", key, false);
        if (!j) return;
        expectArray(*j, key);
        if (list.error) throw *list.error;
        out = std::move(list.items);
    }

    void readCamera(const json& j, Camera& c) const {
        const std::string p = "camera";
        expectObject(j, p);
        checkKeys(j, p, {"position", "look_at", "up", "vfov_degrees"});
        req(j, p, "position", c.position);
        req(j, p, "look_at", c.lookAt);
        opt(j, p, "up", c.up);
        opt(j, p, "vfov_degrees", c.vfovDegrees);
    }

    void readRender(const json& j, RenderSettings& r) const {
        const std::string p = "render";
        expectObject(j, p);
        checkKeys(j, p, {"width", "height", "max_depth", "samples_per_pixel", "precision"});
        opt(j, p, "width", r.width);
        opt(j, p, "height", r.height);
        opt(j, p, "max_depth", r.maxDepth);
        opt(j, p, "samples_per_pixel", r.samplesPerPixel);
        if (auto* pr = find(j, p, "precision", false)) {
            const std::string name = string(*pr, "render.precision");
            auto parsed = parsePrecision(name);
            if (!parsed)
                fail("render.precision", "expected \"float\" or \"double\", found " + quoted(name));
            r.precision = *parsed;
        }
    }

    void readMaterial(const json& j, const std::string& p, Material& m) const {
        expectObject(j, p);
        checkKeys(j, p,
                  {"name", "diffuse", "specular", "shininess", "reflectivity", "transparency",
                   "ior", "checker"});
        reqName(j, p, m.name);
        opt(j, p, "diffuse", m.diffuse);
        opt(j, p, "specular", m.specular);
        opt(j, p, "shininess", m.shininess);
        opt(j, p, "reflectivity", m.reflectivity);
        opt(j, p, "transparency", m.transparency);
        opt(j, p, "ior", m.ior);
        if (auto* c = find(j, p, "checker", false)) {
            const std::string cp = p + ".checker";
            expectObject(*c, cp);
            checkKeys(*c, cp, {"color", "size"});
            Checker checker;
            req(*c, cp, "color", checker.color);
            req(*c, cp, "size", checker.size);
            m.checker = checker;
        }
    }

    void readLight(const json& j, const std::string& p, Light& l) const {
        expectObject(j, p);
        checkKeys(j, p, {"name", "position", "color", "intensity"});
        reqName(j, p, l.name);
        req(j, p, "position", l.position);
        opt(j, p, "color", l.color);
        opt(j, p, "intensity", l.intensity);
    }

    void readSphere(const json& j, const std::string& p, Sphere& s) const {
        expectObject(j, p);
        checkKeys(j, p, {"name", "center", "radius", "material"});
        reqName(j, p, s.name);
        req(j, p, "center", s.center);
        req(j, p, "radius", s.radius);
        s.material = string(*find(j, p, "material", true), p + ".material");
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
