#include "document/scene_selection.h"

#include <algorithm>
#include <unordered_map>

#include "document/scene_document.h"

namespace whitted::ui {

const std::string& itemNameOf(const Scene& scene, ItemKind kind, int index) {
    static const std::string none;
    if (index < 0 || index >= itemCount(scene, kind)) return none;
    switch (kind) {
        case ItemKind::Sphere:
            return scene.spheres[index].name;
        case ItemKind::Light:
            return scene.lights[index].name;
        case ItemKind::Material:
            return scene.materials[index].name;
    }
    return none;
}

bool SceneSelection::contains(ItemKind kind, int index) const {
    return kind == kind_ && std::binary_search(indices_.begin(), indices_.end(), index);
}

void SceneSelection::set(ItemKind kind, std::vector<int> indices, int active) {
    const int last = indices.empty() ? -1 : indices.back();
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    indices.erase(indices.begin(), std::lower_bound(indices.begin(), indices.end(), 0));
    if (!std::binary_search(indices.begin(), indices.end(), active)) active = last;
    if (active < 0 && !indices.empty()) active = indices.back();
    if (kind == kind_ && indices == indices_ && active == active_) return;
    kind_ = kind;
    indices_ = std::move(indices);
    active_ = active;
    emit changed();
}

void SceneSelection::selectOne(ItemKind kind, int index) {
    set(kind, index < 0 ? std::vector<int>{} : std::vector<int>{index}, index);
}

void SceneSelection::toggle(ItemKind kind, int index) {
    if (index < 0) return;
    if (kind != kind_) return selectOne(kind, index);
    std::vector<int> indices = indices_;
    const auto at = std::lower_bound(indices.begin(), indices.end(), index);
    if (at != indices.end() && *at == index) {
        indices.erase(at);
        // The active item stays unless it was the one removed.
        set(kind, std::move(indices), index == active_ ? -1 : active_);
        return;
    }
    indices.insert(at, index);
    set(kind, std::move(indices), index);
}

void SceneSelection::rememberNames(const Scene& before) {
    names_.clear();
    names_.reserve(indices_.size());
    for (int i : indices_) names_.push_back(itemNameOf(before, kind_, i));
    activeName_ = itemNameOf(before, kind_, active_);
    countBefore_ = itemCount(before, kind_);
}

void SceneSelection::followNames(const Scene& after) {
    if (names_.empty()) return;
    // A list of the same length only had items edited (a rename among
    // them): every item is where it was.
    if (itemCount(after, kind_) == countBefore_) {
        names_.clear();
        return;
    }
    // Names are unique within a kind (SPEC §6), so a name finds its item.
    std::unordered_map<std::string_view, int> where;
    const int n = itemCount(after, kind_);
    where.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) where.emplace(itemNameOf(after, kind_, i), i);
    std::vector<int> indices;
    int active = -1;
    for (const std::string& name : names_)
        if (auto it = where.find(name); it != where.end()) indices.push_back(it->second);
    if (auto it = where.find(activeName_); it != where.end()) active = it->second;
    names_.clear();
    set(kind_, std::move(indices), active);
}

}  // namespace whitted::ui
