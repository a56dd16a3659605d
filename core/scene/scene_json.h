// What the scene file's parts share and nothing else needs: the reader
// (scene_json_read.cpp), the file loader (scene_load.cpp), the writer
// (scene_io.cpp) and the clipboard's fragments (scene_fragment.cpp), which
// write their items exactly as the file does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace whitted::detail {

// `s` as a JSON string literal, quotes and escapes included.
std::string quoted(const std::string& s);

// One element of a list as the scene file writes it: one line, keys in SPEC order.
std::string jsonItem(const Material& m);
std::string jsonItem(const Light& l);
std::string jsonItem(const Sphere& s);

// A list's elements one a line, indented as inside the file's top-level object.
template <typename T>
std::string jsonList(const std::vector<T>& items) {
    if (items.empty()) return "[]";
    std::string out = "[\n";
    for (std::size_t i = 0; i < items.size(); ++i)
        out.append("    ").append(jsonItem(items[i])).append(i + 1 < items.size() ? ",\n" : "\n");
    return out + "  ]";
}

// A top-level object of the given keys and values (already JSON), one a line.
using JsonFields = std::vector<std::pair<std::string_view, std::string>>;
std::string jsonDocument(const JsonFields& top);

// The fewest bytes a sphere takes in a file, for an upper bound on the
// spheres of a text: reserved pages that stay unused are never touched, so
// they cost address space only. 100 is about the shortest line sceneToJson()
// writes for a sphere of short names.
inline constexpr std::size_t kShortestSavedSphere = 100;

// A scene file's text to its Scene, validated: by readSceneFast()
// (scene_fast_read.h) where it can, else by the full reader, which names what
// is wrong. `capacity` >= size + fastReadPadding().
Scene parseSceneText(const char* text, std::size_t size, std::size_t capacity,
                     const std::string& sourceName);

// The same by the full reader alone (scene_json_read.cpp).
Scene parseSceneFully(const char* text, std::size_t size, const std::string& sourceName);

}  // namespace whitted::detail
