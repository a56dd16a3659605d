// The fast way through a scene file: simdjson's parser over the whole text,
// straight into the Scene's structs. It reads only what the full reader
// (scene_json_read.cpp) would read the same way and hands everything else
// back, so every refusal still comes from the full reader, with its JSON path.
#pragma once

#include <cstddef>
#include <optional>

#include "scene/scene.h"

namespace whitted::detail {

// The bytes the fast reader may read past a text's end (their values do not
// matter): the text's buffer must have this many more.
std::size_t fastReadPadding();

// The Scene a scene file's text holds, before validateScene(); nothing when
// the full reader might refuse the text or read it otherwise: bad syntax, an
// unknown or repeated key, a missing field, a value of the wrong type, a
// number that is not finite in double, text after the top-level object.
// `capacity` >= size + fastReadPadding().
std::optional<Scene> readSceneFast(const char* text, std::size_t size, std::size_t capacity);

}  // namespace whitted::detail
