// Copy and paste of scene items as text (scene_fragment.h): the scene file's
// own per-item writer and reader, and the renaming that makes pasted items fit
// the scene they land in.
#include "scene/scene_fragment.h"

#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "scene/scene_io.h"
#include "scene/scene_json.h"
#include "scene/scene_json_reader.h"

namespace whitted {
namespace {

using nlohmann::json;

const char* const kFragmentFormatName = "whitted-scene-fragment";
const char* const kClipboardSource = "clipboard";

// The items at `indices`, each once, in the list's order: a fragment keeps
// the order the items had in their scene whichever way they were selected.
template <typename T>
std::vector<T> pickInListOrder(const std::vector<T>& items,
                               const std::vector<std::size_t>& indices) {
    std::vector<bool> picked(items.size(), false);
    for (const std::size_t i : indices) picked.at(i) = true;
    std::vector<T> out;
    for (std::size_t i = 0; i < items.size(); ++i)
        if (picked[i]) out.push_back(items[i]);
    return out;
}

std::vector<Material> materialsUsedBy(const Scene& scene, const std::vector<Sphere>& spheres) {
    const auto index = materialIndices(scene);
    std::vector<std::size_t> used;
    for (const Sphere& s : spheres)
        if (const auto it = index.find(s.material); it != index.end())
            used.push_back(static_cast<std::size_t>(it->second));
    return pickInListOrder(scene.materials, used);
}

// ---- reading ------------------------------------------------------------------

bool hasFormat(const json& root, std::string_view format) {
    const auto it = root.find(scene_field::kFormat.key);
    return it != root.end() && it->is_string() && it->get_ref<const std::string&>() == format;
}

// Whether `root` is a whole scene file rather than a fragment; refuses other JSON.
bool isWholeSceneFile(const detail::Reader& reader, const json& root) {
    reader.expectObject(root, "");
    if (hasFormat(root, kSceneFormatName)) return true;
    if (hasFormat(root, kFragmentFormatName)) return false;
    const auto it = root.find(scene_field::kFormat.key);
    reader.fail("format", "expected \"" + std::string(kFragmentFormatName) +
                              "\" or \"whitted-scene\", found " +
                              (it == root.end() ? std::string("no format") : it->dump()));
}

Scene readFragmentLists(const detail::Reader& reader, const json& root, detail::Lists& lists) {
    using namespace scene_field;
    reader.checkKeys(root, "", {kFormat, kVersion, kMaterials, kSpheres, kLights});
    reader.readVersion(root, kFragmentFormatVersion);
    Scene items;
    reader.take(root, kMaterials, lists.materials, items.materials);
    reader.take(root, kLights, lists.lights, items.lights);
    reader.take(root, kSpheres, lists.spheres, items.spheres);
    return items;
}

// The pasted items as a scene of default camera and settings, refused as the
// scene file would refuse them. A default scene's camera and settings are
// valid, so validateScene() can only find the items' problems.
Scene readPastedItems(const std::string& text) {
    const detail::Reader reader(kClipboardSource);
    detail::Lists lists;
    const json root = detail::parseTopLevel(text, reader, lists);
    Scene items = isWholeSceneFile(reader, root) ? reader.read(root, lists)
                                                 : readFragmentLists(reader, root, lists);
    if (auto problem = validateScene(items)) reader.fail(problem->jsonPath, problem->reason);
    return items;
}

// ---- naming -------------------------------------------------------------------

// "stem N" as its stem and N, anything else as itself and 1, so that a
// renamed copy of "ball 2" is "ball 3", not "ball 2 2".
std::pair<std::string, long> stemAndOrdinal(const std::string& name) {
    const std::size_t space = name.rfind(' ');
    const std::size_t digits = space == std::string::npos ? 0 : name.size() - space - 1;
    if (space == std::string::npos || space == 0 || digits == 0 || digits > 9) return {name, 1};
    for (std::size_t i = space + 1; i < name.size(); ++i)
        if (name[i] < '0' || name[i] > '9') return {name, 1};
    return {name.substr(0, space), std::stol(name.substr(space + 1))};
}

// The names of one list: those of the scene pasted into, and those the
// pasted items keep or are given. A new name avoids every pasted item's name
// too, so an item that does not clash keeps its own.
class PasteNames {
  public:
    // The views point into `existing`, which must outlive this.
    template <typename T>
    PasteNames(const std::vector<T>& existing, const std::vector<T>& pasted) {
        existing_.reserve(existing.size());
        for (const T& item : existing) existing_.insert(item.name);
        for (const T& item : pasted) given_.insert(item.name);
    }

    bool clashes(const std::string& name) const { return existing_.count(name) > 0; }

    std::string renamed(const std::string& name) {
        auto [stem, ordinal] = stemAndOrdinal(name);
        std::string candidate;
        do {
            candidate = stem + " " + std::to_string(++ordinal);
        } while (existing_.count(candidate) > 0 || given_.count(candidate) > 0);
        given_.insert(candidate);
        return candidate;
    }

  private:
    std::unordered_set<std::string_view> existing_;
    std::unordered_set<std::string> given_;
};

// Appends the pasted materials `into` lacks to out.scene; returns the name
// each pasted material goes by in the result.
std::unordered_map<std::string, std::string> pasteMaterials(const Scene& into,
                                                            const std::vector<Material>& pasted,
                                                            PasteResult& out) {
    PasteNames names(into.materials, pasted);
    const auto existing = materialIndices(into);
    std::unordered_map<std::string, std::string> nameNow;
    for (const Material& m : pasted) {
        const auto it = existing.find(m.name);
        if (it != existing.end() && into.materials[static_cast<std::size_t>(it->second)] == m) {
            nameNow[m.name] = m.name;
            ++out.materialsReused;
            continue;
        }
        Material added = m;
        if (it != existing.end()) added.name = names.renamed(m.name);
        nameNow[m.name] = added.name;
        out.scene.materials.push_back(std::move(added));
        ++out.materialsAdded;
    }
    return nameNow;
}

// Appends `pasted` to `list` (a copy of `existing`), renaming those whose
// names clash; returns their indices in `list`.
template <typename T>
std::vector<std::size_t> appendRenamed(const std::vector<T>& existing, const std::vector<T>& pasted,
                                       std::vector<T>& list, std::size_t& renamed) {
    PasteNames names(existing, pasted);
    std::vector<std::size_t> indices;
    list.reserve(list.size() + pasted.size());
    for (const T& item : pasted) {
        indices.push_back(list.size());
        list.push_back(item);
        if (!names.clashes(item.name)) continue;
        list.back().name = names.renamed(item.name);
        ++renamed;
    }
    return indices;
}

}  // namespace

std::string fragmentToJson(const Scene& scene, const std::vector<std::size_t>& spheres,
                           const std::vector<std::size_t>& lights) {
    const std::vector<Sphere> picked = pickInListOrder(scene.spheres, spheres);
    using namespace scene_field;
    return detail::jsonDocument({
        {kFormat.key, detail::quoted(kFragmentFormatName)},
        {kVersion.key, std::to_string(kFragmentFormatVersion)},
        {kMaterials.key, detail::jsonList(materialsUsedBy(scene, picked))},
        {kSpheres.key, detail::jsonList(picked)},
        {kLights.key, detail::jsonList(pickInListOrder(scene.lights, lights))},
    });
}

// Everything is read and checked before anything is appended, so a refusal
// leaves no half-pasted scene behind.
PasteResult pasteFragment(const Scene& into, const std::string& text) {
    const Scene pasted = readPastedItems(text);
    PasteResult out;
    out.scene = into;
    const auto materialNow = pasteMaterials(into, pasted.materials, out);
    out.newSpheres = appendRenamed(into.spheres, pasted.spheres, out.scene.spheres, out.renamed);
    for (const std::size_t i : out.newSpheres)
        out.scene.spheres[i].material = materialNow.at(out.scene.spheres[i].material);
    out.newLights = appendRenamed(into.lights, pasted.lights, out.scene.lights, out.renamed);
    return out;
}

}  // namespace whitted
