// JSON scene files, format "whitted-scene" version 1 (SPEC §6): load with full
// validation, save byte-stable and atomically.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "scene/scene.h"
#include "scene/scene_fields.h"

namespace whitted {

inline constexpr std::string_view kSceneFormatName = "whitted-scene";
inline constexpr int kSceneFormatVersion = 1;

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

// The largest scene file loadScene() reads, and why, for the refusal's message.
// A loaded scene takes about as much memory as its file, and loading holds the
// file's text and the parser's index of it besides (a 1M-sphere file of 144 MB
// peaks at 369 MB while loading), so a quarter of the machine's memory opens any
// scene the machine can work with, while a mistaken multi-gigabyte file is
// refused before it is read. Never less than kMinSceneFileLimit.
struct SceneFileLimit {
    std::uintmax_t bytes;
    std::string why;  // e.g. "a quarter of this machine's memory"
};
inline constexpr std::uintmax_t kMinSceneFileLimit = std::uintmax_t(64) << 20;
SceneFileLimit sceneFileLimit();

// Told, from the loading thread, how many bytes of the file are read so far
// and its size (called once a MB; after a whole read, last with done == total).
using LoadProgress = std::function<void(std::uintmax_t done, std::uintmax_t total)>;

// Reads the file whole, then parses it (scene_fast_read.h). Throws SceneError
// (unreadable files and files over the limit included: refused unread, or a
// pipe once it passes the limit).
Scene loadScene(const std::filesystem::path& file, const LoadProgress& progress = {},
                const SceneFileLimit& limit = sceneFileLimit());

// What broke a rule of SPEC §6, for a program to tell apart without reading
// the reason's words.
enum class ProblemKind {
    BreaksRule,        // the field's value breaks its FieldRule
    NotFinite,         // a number that is not finite (any rule)
    EmptyName,         // an item without a name
    RepeatedName,      // a name an earlier item of the list has
    UnknownMaterial,   // a sphere's material that no material is named
    LookAtIsPosition,  // the camera looks at where it stands
    UpIsZero,          // the camera's up vector is zero
    UpAlongView,       // the camera's up vector is parallel to its view
};

// The list an item is in, for a problem with one of its fields.
enum class SceneList { None, Materials, Lights, Spheres };

// The semantic rules of SPEC §6 for a scene built in memory (the editor's):
// "<json path>: <reason>" as the loader says them, and the same typed.
struct SceneProblem {
    std::string jsonPath;
    std::string reason;
    ProblemKind kind = ProblemKind::BreaksRule;
    const SceneField* field = nullptr;  // the field (scene_fields.h), when it is one's
    SceneList list = SceneList::None;   // the item whose field it is, if any
    std::size_t index = 0;
};
std::optional<SceneProblem> validateScene(const Scene& scene);

// validateScene(after) for an edit of a valid scene `before`, in time
// proportional to what the edit changed (plus a comparison of the two): the
// editor validates every edit, and a scene of 100,000 spheres spent most of
// an edit hashing names no edit had touched. Same result, same message.
std::optional<SceneProblem> validateEdit(const Scene& before, const Scene& after);

// validateEdit for an edit of a valid scene that changed one item alone and
// kept its name: `edited` is the item as the edit leaves it and `index` its
// place in its list; `scene`, for a sphere's materials, need not hold the edit
// yet. Constant time but for a sphere's material, looked up by name.
std::optional<SceneProblem> validateSphereEdit(const Scene& scene, const Sphere& edited,
                                               std::size_t index);
std::optional<SceneProblem> validateLightEdit(const Light& edited, std::size_t index);
std::optional<SceneProblem> validateMaterialEdit(const Material& edited, std::size_t index);
// validateEdit for an edit of a valid scene that changed only its camera,
// render settings, background or ambient light, as whitted-render's flags,
// plans and turntable do: those fields' rules alone, in constant time (a
// second validateScene() of a million spheres took 30 to 50 ms).
std::optional<SceneProblem> validateSettingsEdit(const Scene& after);

// The canonical text of a scene: keys in SPEC order, one object per line inside
// lists, numbers in shortest round-trip form. Equal scenes give equal bytes.
std::string sceneToJson(const Scene& scene);

// A digest of sceneToJson() without the render settings (16 hex digits,
// FNV-1a): equal for scenes that sameSceneContent() finds equal, and, but
// for a collision, different for any others. For files that record which
// scene they were made for.
std::string sceneContentDigest(const Scene& scene);

// Writes sceneToJson() to a temporary file beside `file`, then renames it over
// `file`, so the old file stays whole if anything fails. Throws std::runtime_error.
void saveScene(const Scene& scene, const std::filesystem::path& file);

}  // namespace whitted
