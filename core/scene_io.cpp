// Loading walks the JSON once, checking structure (keys, types, finiteness) with
// the JSON path at hand, then applies validateScene() for the semantic rules, so
// the editor and the loader refuse exactly the same scenes.
#include "scene_io.h"

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "atomic_file.h"

namespace whitted {
namespace fs = std::filesystem;
using nlohmann::json;

SceneError::SceneError(std::string file, std::string jsonPath, std::string reason)
    : std::runtime_error(file + ": " + (jsonPath.empty() ? "" : jsonPath + ": ") + reason),
      file_(std::move(file)),
      path_(std::move(jsonPath)),
      reason_(std::move(reason)) {}

namespace {

std::string typeName(const json& j) {
    if (j.is_number()) return "a number";
    if (j.is_string()) return "a string";
    if (j.is_boolean()) return "a boolean";
    if (j.is_array()) return "an array";
    if (j.is_object()) return "an object";
    return "null";
}

std::string quoted(const std::string& s) {
    return json(s).dump();
}

std::string joinKey(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

// Reads one JSON document into a Scene; every failure names the JSON path.
class Reader {
  public:
    explicit Reader(std::string file) : file_(std::move(file)) {}

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

    Scene read(const json& root) const {
        expectObject(root, "");
        checkKeys(root, "",
                  {"format", "version", "camera", "render", "background", "ambient", "materials",
                   "lights", "spheres"});
        const json* format = find(root, "", "format", true);
        if (!format->is_string() || format->get<std::string>() != "whitted-scene")
            fail("format", "expected \"whitted-scene\", found " + format->dump());
        const int version = integer(*find(root, "", "version", true), "version");
        if (version > kSceneFormatVersion)
            fail("version", std::to_string(version) + " is newer than this program reads (" +
                                std::to_string(kSceneFormatVersion) + ")");
        if (version < 1) fail("version", "must be at least 1");

        Scene scene;
        readCamera(*find(root, "", "camera", true), scene.camera);
        if (auto* r = find(root, "", "render", false)) readRender(*r, scene.render);
        opt(root, "", "background", scene.background);
        opt(root, "", "ambient", scene.ambient);
        readList(root, "materials", scene.materials, &Reader::readMaterial);
        readList(root, "lights", scene.lights, &Reader::readLight);
        readList(root, "spheres", scene.spheres, &Reader::readSphere);
        return scene;
    }

  private:
    template <typename T>
    void readList(const json& root, const char* key, std::vector<T>& out,
                  void (Reader::*readOne)(const json&, const std::string&, T&) const) const {
        const json* list = find(root, "", key, false);
        if (!list) return;
        expectArray(*list, key);
        out.resize(list->size());
        for (size_t i = 0; i < list->size(); ++i)
            (this->*readOne)((*list)[i], std::string(key) + "[" + std::to_string(i) + "]", out[i]);
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

    std::string file_;
};

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
    // Hashed, and paths built only for a problem: the editor validates every
    // edit, and a scene of 100,000 spheres spent 40 ms here with a std::map.
    std::unordered_map<std::string_view, size_t> seen;
    seen.reserve(items.size());
    for (size_t i = 0; i < items.size(); ++i) {
        if (items[i].name.empty())
            return SceneProblem{indexed(list, i) + ".name", "must not be empty"};
        auto [it, inserted] = seen.emplace(items[i].name, i);
        if (!inserted)
            return SceneProblem{indexed(list, i) + ".name", "duplicate name " +
                                                                quoted(items[i].name) + " (also " +
                                                                indexed(list, it->second) + ")"};
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
    std::unordered_set<std::string_view> materialNames;
    for (const Material& m : scene.materials) materialNames.insert(m.name);
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

namespace {

// Builds the DOM like json::parse, but remembers where in the document it is,
// so that a number too large for a double (1e999, the only way JSON can spell
// infinity) is refused with its JSON path like every other bad value.
class PathTrackingSax {
  public:
    PathTrackingSax(json& result, const std::string& file) : dom_(result, true), file_(file) {}

    bool null() { return value(), dom_.null(); }
    bool boolean(bool v) { return value(), dom_.boolean(v); }
    bool number_integer(json::number_integer_t v) { return value(), dom_.number_integer(v); }
    bool number_unsigned(json::number_unsigned_t v) { return value(), dom_.number_unsigned(v); }
    bool number_float(json::number_float_t v, const json::string_t& s) {
        return value(), dom_.number_float(v, s);
    }
    bool string(json::string_t& v) { return value(), dom_.string(v); }
    bool binary(json::binary_t& v) { return value(), dom_.binary(v); }
    bool start_object(std::size_t n) {
        value();
        frames_.push_back({false, {}, -1});
        return dom_.start_object(n);
    }
    bool key(json::string_t& k) {
        frames_.back().key = k;
        return dom_.key(k);
    }
    bool end_object() {
        frames_.pop_back();
        return dom_.end_object();
    }
    bool start_array(std::size_t n) {
        value();
        frames_.push_back({true, {}, -1});
        return dom_.start_array(n);
    }
    bool end_array() {
        frames_.pop_back();
        return dom_.end_array();
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::json::exception& e) {
        std::string what = e.what();  // "[json.exception.parse_error.101] parse error at ..."
        const auto pos = what.find("] ");
        if (pos != std::string::npos) what = what.substr(pos + 2);
        if (e.id == 406) {  // number overflow: the value that failed is the next one here
            if (!frames_.empty() && frames_.back().isArray) ++frames_.back().index;
            throw SceneError(file_, path(), "must be a finite number (" + what + ")");
        }
        throw SceneError(file_, "", "invalid JSON: " + what);
    }

  private:
    struct Frame {
        bool isArray;
        std::string key;
        long index;
    };

    void value() {
        if (!frames_.empty() && frames_.back().isArray) ++frames_.back().index;
    }

    std::string path() const {
        std::string p;
        for (const Frame& f : frames_) {
            if (f.isArray) {
                p += "[" + std::to_string(f.index) + "]";
            } else {
                if (!p.empty()) p += ".";
                p += f.key;
            }
        }
        return p;
    }

    nlohmann::detail::json_sax_dom_parser<json> dom_;
    const std::string& file_;
    std::vector<Frame> frames_;
};

}  // namespace

Scene parseScene(const std::string& text, const std::string& sourceName) {
    json root;
    PathTrackingSax sax(root, sourceName);
    json::sax_parse(text, &sax);
    Scene scene = Reader(sourceName).read(root);
    if (auto problem = validateScene(scene))
        throw SceneError(sourceName, problem->jsonPath, problem->reason);
    return scene;
}

Scene loadScene(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SceneError(file.string(), "", "cannot open file");
    std::error_code noSize;
    const std::uintmax_t size = fs::file_size(file, noSize);
    if (!noSize && size > kMaxSceneFileBytes) {
        std::ostringstream reason;
        reason << "is " << (size + (1u << 20) - 1) / (1u << 20) << " MB; scene files larger than "
               << kMaxSceneFileBytes / (1u << 20) << " MB are refused";
        throw SceneError(file.string(), "", reason.str());
    }
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw SceneError(file.string(), "", "cannot read file");
    return parseScene(text.str(), file.string());
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

using Fields = std::vector<std::pair<const char*, std::string>>;

std::string object(const Fields& fields) {
    std::string out = "{";
    for (size_t i = 0; i < fields.size(); ++i) {
        if (i) out += ", ";
        out.append("\"").append(fields[i].first).append("\": ").append(fields[i].second);
    }
    return out + "}";
}

template <typename T, typename F>
std::string list(const std::vector<T>& items, F toObject) {
    if (items.empty()) return "[]";
    std::string out = "[\n";
    for (size_t i = 0; i < items.size(); ++i)
        out.append("    ").append(toObject(items[i])).append(i + 1 < items.size() ? ",\n" : "\n");
    return out + "  ]";
}

}  // namespace

std::string sceneToJson(const Scene& s) {
    const Camera& c = s.camera;
    const RenderSettings& r = s.render;
    Fields top = {
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
        {"materials", list(s.materials,
                           [](const Material& m) {
                               Fields f = {{"name", quoted(m.name)},
                                           {"diffuse", vec(m.diffuse)},
                                           {"specular", num(m.specular)},
                                           {"shininess", num(m.shininess)},
                                           {"reflectivity", num(m.reflectivity)},
                                           {"transparency", num(m.transparency)},
                                           {"ior", num(m.ior)}};
                               if (m.checker)
                                   f.push_back(
                                       {"checker", object({{"color", vec(m.checker->color)},
                                                           {"size", num(m.checker->size)}})});
                               return object(f);
                           })},
        {"lights", list(s.lights,
                        [](const Light& l) {
                            return object({{"name", quoted(l.name)},
                                           {"position", vec(l.position)},
                                           {"color", vec(l.color)},
                                           {"intensity", num(l.intensity)}});
                        })},
        {"spheres", list(s.spheres,
                         [](const Sphere& sp) {
                             return object({{"name", quoted(sp.name)},
                                            {"center", vec(sp.center)},
                                            {"radius", num(sp.radius)},
                                            {"material", quoted(sp.material)}});
                         })},
    };
    std::string out = "{\n";
    for (size_t i = 0; i < top.size(); ++i)
        out.append("  \"")
            .append(top[i].first)
            .append("\": ")
            .append(top[i].second)
            .append(i + 1 < top.size() ? ",\n" : "\n");
    return out + "}\n";
}

void saveScene(const Scene& scene, const fs::path& file) {
    const std::string text = sceneToJson(scene);
    try {
        replaceFileAtomically(file, [&](const fs::path& temp) { writeAllBytes(temp, text); });
    } catch (const std::system_error& e) {
        throw std::runtime_error(file.string() + ": " + e.code().message());
    }
}

}  // namespace whitted
