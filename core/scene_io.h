// JSON scene files, format "whitted-scene" version 1 (SPEC §6): load with full
// validation, save byte-stable and atomically.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "scene.h"

namespace whitted {

inline constexpr int kSceneFormatVersion = 1;

// Files above this are refused before they are read: 64 MB hold about 600,000
// spheres, six times the largest scene the editor is tested with, while a
// mistaken multi-gigabyte file would otherwise be read whole into memory.
inline constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t(64) << 20;

// A refused scene. what() is the whole user-facing message:
// "<file>: <json path>: <reason>", e.g. "a.json: spheres[2].radius: must be > 0".
class SceneError : public std::runtime_error {
  public:
    SceneError(std::string file, std::string jsonPath, std::string reason);
    const std::string& file() const { return file_; }
    const std::string& jsonPath() const { return path_; }
    const std::string& reason() const { return reason_; }

  private:
    std::string file_, path_, reason_;
};

// Parses scene text; `sourceName` names the file in error messages. Throws SceneError.
Scene parseScene(const std::string& text, const std::string& sourceName);

// Reads and parses a file. Throws SceneError (unreadable files and files over
// kMaxSceneFileBytes included).
Scene loadScene(const std::filesystem::path& file);

// The semantic rules of SPEC §6 for a scene built in memory (the editor's), as
// "<json path>: <reason>", or nothing when the scene is valid.
struct SceneProblem {
    std::string jsonPath;
    std::string reason;
};
std::optional<SceneProblem> validateScene(const Scene& scene);

// validateScene(after) for an edit of a valid scene `before`, in time
// proportional to what the edit changed (plus a comparison of the two): the
// editor validates every edit, and a scene of 100,000 spheres spent most of
// an edit hashing names no edit had touched. Same result, same message.
std::optional<SceneProblem> validateEdit(const Scene& before, const Scene& after);

// The canonical text of a scene: keys in SPEC order, one object per line inside
// lists, numbers in shortest round-trip form. Equal scenes give equal bytes.
std::string sceneToJson(const Scene& scene);

// Writes sceneToJson() to a temporary file beside `file`, then renames it over
// `file`, so the old file stays whole if anything fails. Throws std::runtime_error.
void saveScene(const Scene& scene, const std::filesystem::path& file);

}  // namespace whitted
