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

}  // namespace whitted::detail
