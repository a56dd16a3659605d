// What the scene file's parts share and nothing else needs: the reader
// (scene_json_read.cpp), the file loader (scene_load.cpp) and the writer
// (scene_io.cpp).
#pragma once

#include <iosfwd>
#include <string>

#include "scene.h"

namespace whitted::detail {

// `s` as a JSON string literal, quotes and escapes included.
std::string quoted(const std::string& s);

// parseScene() reading from a stream as it goes, for files too large to hold whole.
Scene parseScene(std::istream& text, const std::string& sourceName);

}  // namespace whitted::detail
