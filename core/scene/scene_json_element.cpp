#include "scene/scene_json_element.h"

namespace whitted::detail {

ElementEvents::json ElementEvents::toJson() const {
    json value;
    nlohmann::detail::json_sax_dom_parser<json> dom(value, true);
    for (std::size_t i = 0; i < size_; ++i) {
        const Event& e = events_[i];
        std::string text = e.text;
        switch (e.kind) {
            case Kind::Null:
                dom.null();
                break;
            case Kind::Boolean:
                dom.boolean(e.integer != 0);
                break;
            case Kind::Integer:
                dom.number_integer(e.integer);
                break;
            case Kind::Unsigned:
                dom.number_unsigned(e.unsignedInteger);
                break;
            case Kind::Float:
                dom.number_float(e.number, text);
                break;
            case Kind::String:
                dom.string(text);
                break;
            case Kind::Key:
                dom.key(text);
                break;
            case Kind::StartObject:
                dom.start_object(std::size_t(-1));
                break;
            case Kind::EndObject:
                dom.end_object();
                break;
            case Kind::StartArray:
                dom.start_array(std::size_t(-1));
                break;
            case Kind::EndArray:
                dom.end_array();
                break;
        }
    }
    return value;
}

bool ElementEvents::isNumber(std::size_t i) const {
    const Kind k = events_[i].kind;
    return k == Kind::Integer || k == Kind::Unsigned || k == Kind::Float;
}

// As json::get<double>() converts each kind of number.
double ElementEvents::numberAt(std::size_t i) const {
    const Event& e = events_[i];
    if (e.kind == Kind::Integer) return static_cast<double>(e.integer);
    if (e.kind == Kind::Unsigned) return static_cast<double>(e.unsignedInteger);
    return e.number;
}

bool ElementEvents::readCanonicalSphere(Sphere& out) const {
    // { + 4 keys + name + [x, y, z] + radius + material + }
    constexpr std::size_t kEvents = 14;
    if (size_ != kEvents || events_[0].kind != Kind::StartObject ||
        events_[kEvents - 1].kind != Kind::EndObject)
        return false;
    enum : unsigned { kName = 1, kCenter = 2, kRadius = 4, kMaterial = 8 };
    unsigned seen = 0;
    for (std::size_t i = 1; i + 1 < kEvents;) {
        if (events_[i].kind != Kind::Key) return false;
        const std::string& key = events_[i++].text;
        const Kind kind = events_[i].kind;
        if (key == "name" && !(seen & kName) && kind == Kind::String) {
            out.name = events_[i++].text;
            seen |= kName;
        } else if (key == "material" && !(seen & kMaterial) && kind == Kind::String) {
            out.material = events_[i++].text;
            seen |= kMaterial;
        } else if (key == "radius" && !(seen & kRadius) && isNumber(i)) {
            out.radius = numberAt(i++);
            seen |= kRadius;
        } else if (key == "center" && !(seen & kCenter) && kind == Kind::StartArray &&
                   i + 4 < kEvents && isNumber(i + 1) && isNumber(i + 2) && isNumber(i + 3) &&
                   events_[i + 4].kind == Kind::EndArray) {
            out.center = Vec3(numberAt(i + 1), numberAt(i + 2), numberAt(i + 3));
            i += 5;
            seen |= kCenter;
        } else {
            return false;
        }
    }
    return seen == (kName | kCenter | kRadius | kMaterial);
}

}  // namespace whitted::detail
