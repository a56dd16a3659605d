// Scene fragments: the editor's copy and paste between windows, through the
// system clipboard as text. A fragment holds some spheres and lights and the
// materials its spheres use, each written and read exactly as the scene file
// (SPEC §6) writes and reads it:
//
//   {"format": "whitted-scene-fragment", "version": 1,
//    "materials": [...], "spheres": [...], "lights": [...]}
//
// A whole scene file's text pastes too: its materials, spheres and lights.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace whitted {

inline constexpr int kFragmentFormatVersion = 1;

// The spheres and lights at the given indices of `scene` (a valid scene), each
// once and in the scene's order whatever the order or repeats of the indices,
// and the materials those spheres use, in the scene's order. Throws
// std::out_of_range for an index past its list.
std::string fragmentToJson(const Scene& scene, const std::vector<std::size_t>& spheres,
                           const std::vector<std::size_t>& lights);

struct PasteResult {
    Scene scene;                                     // `into` with the fragment appended
    std::vector<std::size_t> newSpheres, newLights;  // the pasted items' indices in `scene`
    std::size_t renamed = 0;                         // pasted spheres and lights given a new name
    std::size_t materialsReused = 0;  // fragment materials `into` already had, same in every field
    std::size_t materialsAdded = 0;   // fragment materials appended (renamed ones included)
};

// `into` (a valid scene) with the items of the fragment or scene file `text`
// appended, and the result valid:
// - a sphere or light whose name `into` has is renamed "ball" -> "ball 2",
//   "ball 3", ... ("ball 2" -> "ball 3"), to a name neither `into` nor the
//   fragment has;
// - a material `into` has under the same name with the same fields is reused;
//   one whose name `into` has with other fields is added under a new name
//   ("glass" -> "glass 2"); any other is added as it is. Pasted spheres name
//   the material they end up using.
// Throws SceneError (file "clipboard") for text that is not JSON, not a
// fragment or scene file, or that the scene file's rules refuse, with the
// file's messages and JSON paths (e.g. "spheres[0].radius") relative to the
// text; nothing is pasted then.
PasteResult pasteFragment(const Scene& into, const std::string& text);

}  // namespace whitted
