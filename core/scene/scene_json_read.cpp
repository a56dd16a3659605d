// Scene text to Scene without a DOM of the whole file: the SAX handler below
// builds a DOM of the small top-level values only; each element of the lists
// (materials, lights, spheres) is recorded as its SAX events
// (scene_json_element.h), read into its struct and dropped, so a file of a
// million spheres never holds more than one sphere's events. Every refusal is
// the one reading the whole DOM gave, in the same order: JSON syntax anywhere
// first, then structure in Reader::read's order (scene_json_reader.h), then
// validateScene() for the semantic rules.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_fast_read.h"
#include "scene/scene_io.h"
#include "scene/scene_json.h"
#include "scene/scene_json_element.h"
#include "scene/scene_json_reader.h"

namespace whitted {
namespace {

using detail::Lists;
using detail::Reader;
using detail::Streamed;
using nlohmann::json;

SceneList listNamed(std::string_view key) {
    if (key == scene_field::kMaterials.key) return SceneList::Materials;
    if (key == scene_field::kLights.key) return SceneList::Lights;
    if (key == scene_field::kSpheres.key) return SceneList::Spheres;
    return SceneList::None;
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
            const SceneList kind = listNamed(frames_.back().key);
            if (kind != SceneList::None) {
                value();
                frames_.push_back({true, {}, -1});
                list_ = kind;
                if (kind == SceneList::Spheres) reserveSpheres();
                return dom_.start_array(n);  // stays empty: the elements go to lists_
            }
        }
        open(true);
        return forward([n](auto& d) { return d.start_array(n); });
    }
    bool end_array() {
        frames_.pop_back();
        if (list_ != SceneList::None && !inElement_ && frames_.size() == 1) {
            list_ = SceneList::None;
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
        return list_ != SceneList::None && !inElement_ && frames_.size() == 2;
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
    // loading time in moves and fresh pages.
    void reserveSpheres() {
        lists_.spheres.items.reserve(std::size_t(lists_.textBytes / detail::kShortestSavedSphere));
    }

    void reset(SceneList kind) {
        if (kind == SceneList::Materials) lists_.materials = {};
        if (kind == SceneList::Lights) lists_.lights = {};
        if (kind == SceneList::Spheres) lists_.spheres = {};
    }

    void finishElement() {
        // Only files the fast reader (scene_fast_read.h) handed back come
        // here, to be refused with the path of what is wrong: no shortcut.
        if (list_ == SceneList::Spheres) readElement(lists_.spheres, &Reader::readSphere);
        if (list_ == SceneList::Materials) readElement(lists_.materials, &Reader::readMaterial);
        if (list_ == SceneList::Lights) readElement(lists_.lights, &Reader::readLight);
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
    SceneList list_ = SceneList::None;
    Lists& lists_;
    const Reader& reader_;
    const std::string& file_;
    std::vector<Frame> frames_;
};

template <typename... Input>
json parseTop(const Reader& reader, Lists& lists, Input&&... input) {
    json root;
    StreamingSax sax(root, lists, reader, reader.file());
    json::sax_parse(std::forward<Input>(input)..., &sax);
    return root;
}

template <typename... Input>
Scene parse(const std::string& sourceName, std::uintmax_t textBytes, Input&&... input) {
    const Reader reader(sourceName);
    Lists lists;
    lists.textBytes = textBytes;
    const json root = parseTop(reader, lists, std::forward<Input>(input)...);
    Scene scene = reader.read(root, lists);
    if (auto problem = validateScene(scene))
        throw SceneError(sourceName, problem->jsonPath, problem->reason);
    return scene;
}

}  // namespace

json detail::parseTopLevel(const std::string& text, const Reader& reader, Lists& lists) {
    lists.textBytes = text.size();
    return parseTop(reader, lists, text);
}

Scene detail::parseSceneText(const char* text, std::size_t size, std::size_t capacity,
                             const std::string& sourceName) {
    if (std::optional<Scene> scene = readSceneFast(text, size, capacity)) {
        if (auto problem = validateScene(*scene))
            throw SceneError(sourceName, problem->jsonPath, problem->reason);
        return std::move(*scene);
    }
    return parseSceneFully(text, size, sourceName);
}

Scene detail::parseSceneFully(const char* text, std::size_t size, const std::string& sourceName) {
    return parse(sourceName, size, text, text + size);
}

Scene parseScene(const std::string& text, const std::string& sourceName) {
    std::string padded = text;
    padded.resize(text.size() + detail::fastReadPadding());
    return detail::parseSceneText(padded.data(), text.size(), padded.size(), sourceName);
}

}  // namespace whitted
