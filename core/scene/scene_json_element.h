// One element of a scene file's list (a sphere, a light, a material) as the
// SAX events that spelled it, replayed into a DOM of that element alone for
// the reader (scene_json_reader.h): a file's lists are never held as one DOM.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace whitted::detail {

class ElementEvents {
  public:
    using json = nlohmann::json;

    // The SAX interface's events, recorded (names as nlohmann's json_sax).
    bool null() { return add(Kind::Null), true; }
    bool boolean(bool v) { return add(Kind::Boolean).integer = v, true; }
    bool number_integer(json::number_integer_t v) { return add(Kind::Integer).integer = v, true; }
    bool number_unsigned(json::number_unsigned_t v) {
        return add(Kind::Unsigned).unsignedInteger = v, true;
    }
    bool number_float(json::number_float_t v, const json::string_t& s) {
        Event& e = add(Kind::Float);
        e.number = v;
        e.text = s;
        return true;
    }
    bool string(json::string_t& v) { return add(Kind::String).text = v, true; }
    bool binary(json::binary_t&) { return false; }  // JSON text has no binary values
    bool key(json::string_t& k) { return add(Kind::Key).text = k, true; }
    bool start_object(std::size_t) { return add(Kind::StartObject), true; }
    bool end_object() { return add(Kind::EndObject), true; }
    bool start_array(std::size_t) { return add(Kind::StartArray), true; }
    bool end_array() { return add(Kind::EndArray), true; }

    void clear() { size_ = 0; }

    // The element as json::parse would have built it.
    json toJson() const;

  private:
    enum class Kind : std::uint8_t {
        Null,
        Boolean,
        Integer,
        Unsigned,
        Float,
        String,
        Key,
        StartObject,
        EndObject,
        StartArray,
        EndArray
    };
    struct Event {
        Kind kind;
        std::int64_t integer;
        std::uint64_t unsignedInteger;
        double number;
        std::string text;
    };

    // Events are reused from element to element, their strings' storage too.
    Event& add(Kind kind) {
        if (size_ == events_.size()) events_.emplace_back();
        Event& e = events_[size_++];
        e.kind = kind;
        return e;
    }

    std::vector<Event> events_;
    std::size_t size_ = 0;
};

}  // namespace whitted::detail
