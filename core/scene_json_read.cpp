// Scene text to Scene without a DOM of the whole file: the SAX handler below
// builds a DOM of the small top-level values, but each element of the lists
// (materials, lights, spheres) alone, reads it into its struct and drops it.
// A file of a million spheres then never holds more than one sphere's DOM.
// Every refusal is the one reading the whole DOM gave, in the same order:
// JSON syntax anywhere first, then structure in Reader::read's order, then
// validateScene() for the semantic rules.
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene_io.h"
#include "scene_json.h"
#include "scene_json_element.h"

namespace whitted {
namespace {

using detail::quoted;
using nlohmann::json;

std::string typeName(const json& j) {
    if (j.is_number()) return "a number";
    if (j.is_string()) return "a string";
    if (j.is_boolean()) return "a boolean";
    if (j.is_array()) return "an array";
    if (j.is_object()) return "an object";
    return "null";
}

std::string joinKey(const std::string& parent, const std::string& key) {
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
        take(root, "materials", lists.materials, scene.materials);
        take(root, "lights", lists.lights, scene.lights);
        take(root, "spheres", lists.spheres, scene.spheres);
        return scene;
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

enum class ListKind { None, Materials, Lights, Spheres };

ListKind listNamed(std::string_view key) {
    if (key == "materials") return ListKind::Materials;
    if (key == "lights") return ListKind::Lights;
    if (key == "spheres") return ListKind::Spheres;
    return ListKind::None;
}

// Builds the DOM like json::parse, except for the lists' elements (see the
// top of the file), and remembers where in the document it is, so that a
// number too large for a double (1e999, the only way JSON can spell infinity)
// is refused with its JSON path like every other bad value.
class StreamingSax {
  public:
    StreamingSax(json& root, Lists& lists, const Reader& reader, const std::string& file)
        : dom_(root, true), lists_(lists), reader_(reader), file_(file) {}

    bool null() {
        return scalar([](auto& d) { return d.null(); });
    }
    bool boolean(bool v) {
        return scalar([v](auto& d) { return d.boolean(v); });
    }
    bool number_integer(json::number_integer_t v) {
        return scalar([v](auto& d) { return d.number_integer(v); });
    }
    bool number_unsigned(json::number_unsigned_t v) {
        return scalar([v](auto& d) { return d.number_unsigned(v); });
    }
    bool number_float(json::number_float_t v, const json::string_t& s) {
        return scalar([&](auto& d) { return d.number_float(v, s); });
    }
    bool string(json::string_t& v) {
        return scalar([&](auto& d) { return d.string(v); });
    }
    bool binary(json::binary_t& v) {
        return scalar([&](auto& d) { return d.binary(v); });
    }
    bool start_object(std::size_t n) {
        open(false);
        return forward([n](auto& d) { return d.start_object(n); });
    }
    bool key(json::string_t& k) {
        frames_.back().key = k;
        // A repeated top-level key replaces the earlier value, as in a DOM.
        if (frames_.size() == 1) reset(listNamed(k));
        return forward([&](auto& d) { return d.key(k); });
    }
    bool end_object() {
        frames_.pop_back();
        return close([](auto& d) { return d.end_object(); });
    }
    bool start_array(std::size_t n) {
        if (frames_.size() == 1 && !frames_.back().isArray) {
            const ListKind kind = listNamed(frames_.back().key);
            if (kind != ListKind::None) {
                value();
                frames_.push_back({true, {}, -1});
                list_ = kind;
                if (kind == ListKind::Spheres) reserveSpheres();
                return dom_.start_array(n);  // stays empty: the elements go to lists_
            }
        }
        open(true);
        return forward([n](auto& d) { return d.start_array(n); });
    }
    bool end_array() {
        frames_.pop_back();
        if (list_ != ListKind::None && !inElement_ && frames_.size() == 1) {
            list_ = ListKind::None;
            return dom_.end_array();
        }
        return close([](auto& d) { return d.end_array(); });
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

    // A value directly inside a streamed list starts an element of its own.
    bool startsElement() const {
        return list_ != ListKind::None && !inElement_ && frames_.size() == 2;
    }

    template <typename F>
    bool forward(F&& event) {
        return inElement_ ? event(element_) : event(dom_);
    }

    template <typename F>
    bool scalar(F&& event) {
        const bool alone = startsElement();
        value();
        if (alone) inElement_ = true;
        const bool ok = forward(event);
        if (alone) finishElement();
        return ok;
    }

    void open(bool isArray) {
        const bool element = startsElement();
        value();
        frames_.push_back({isArray, {}, -1});
        if (element) inElement_ = true;
    }

    template <typename F>
    bool close(F&& event) {
        const bool ok = forward(event);
        if (inElement_ && frames_.size() == 2) finishElement();
        return ok;
    }

    // Growing the vector of a million spheres by doubling cost a tenth of the
    // loading time in moves and fresh pages. The estimate assumes the shortest
    // line sceneToJson() writes for a sphere of short names; reserved pages
    // that stay unused are never touched, so they cost address space only.
    void reserveSpheres() {
        constexpr std::uintmax_t kShortestSavedSphere = 100;
        lists_.spheres.items.reserve(std::size_t(lists_.textBytes / kShortestSavedSphere));
    }

    void reset(ListKind kind) {
        if (kind == ListKind::Materials) lists_.materials = {};
        if (kind == ListKind::Lights) lists_.lights = {};
        if (kind == ListKind::Spheres) lists_.spheres = {};
    }

    void finishElement() {
        if (list_ == ListKind::Spheres && !lists_.spheres.error) {
            Sphere sphere;
            if (element_.readCanonicalSphere(sphere))
                lists_.spheres.items.push_back(std::move(sphere));
            else
                readElement(lists_.spheres, &Reader::readSphere);
        }
        if (list_ == ListKind::Materials) readElement(lists_.materials, &Reader::readMaterial);
        if (list_ == ListKind::Lights) readElement(lists_.lights, &Reader::readLight);
        element_.clear();
        inElement_ = false;
    }

    template <typename T>
    void readElement(Streamed<T>& list, Reader::ReadOne<T> readOne) {
        if (list.error) return;
        const std::string path = frames_[0].key + "[" + std::to_string(frames_[1].index) + "]";
        try {
            T item;
            (reader_.*readOne)(element_.toJson(), path, item);
            list.items.push_back(std::move(item));
        } catch (const SceneError& e) {
            list.error = e;
        }
    }

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
    detail::ElementEvents element_;  // an element of a streamed list, while inside one
    bool inElement_ = false;
    ListKind list_ = ListKind::None;
    Lists& lists_;
    const Reader& reader_;
    const std::string& file_;
    std::vector<Frame> frames_;
};

template <typename... Input>
Scene parse(const std::string& sourceName, std::uintmax_t textBytes, Input&&... input) {
    const Reader reader(sourceName);
    json root;
    Lists lists;
    lists.textBytes = textBytes;
    StreamingSax sax(root, lists, reader, sourceName);
    json::sax_parse(std::forward<Input>(input)..., &sax);
    Scene scene = reader.read(root, lists);
    if (auto problem = validateScene(scene))
        throw SceneError(sourceName, problem->jsonPath, problem->reason);
    return scene;
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& sourceName) {
    return parse(sourceName, text.size(), text);
}

Scene detail::parseScene(ChunkedText& text, const std::string& sourceName) {
    return parse(sourceName, text.size(), ChunkIterator(text), ChunkIterator());
}

}  // namespace whitted
