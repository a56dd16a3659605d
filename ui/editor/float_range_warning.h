// The status bar's warning that a float scene lies outside the range in which
// float renders were measured to match double ones (core/analysis/float_range.h). It
// names the reason and, clicked, switches the scene to double as one undoable
// edit. Re-evaluated on every change of the scene: edit, undo, redo, open, new.
#pragma once

#include <QPushButton>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace whitted::ui {

class SceneDocument;

// Why a scene is outside float's measured range, or nothing (core's floatRangeProblem()).
// It reads the spheres' centres, radii and names, the lights, the materials
// and the camera: the warning asks again only when one of those changed.
using FloatRangeCheck = std::function<std::optional<std::string>(const Scene&)>;

// The warning's text for a scene, or nothing: a double scene never gets one.
std::optional<QString> floatRangeWarningText(const Scene& scene, const FloatRangeCheck& check);

class FloatRangeWarning : public QPushButton {
    Q_OBJECT
  public:
    // `check` defaults to core's floatRangeProblem(); tests pass their own. Give it
    // a parent (the status bar) from the start: it shows itself when needed.
    explicit FloatRangeWarning(SceneDocument* doc, FloatRangeCheck check = {},
                               QWidget* parent = nullptr);

  private:
    void refresh();
    void switchToDouble();

    // What the warning was last worked out from. The spheres are stood for by
    // the document's revision of their geometry and a count of its structure
    // changes (renames among them): a material given to a million spheres
    // changes neither, and the check read every sphere (6 % of the editor's
    // thread in bench_editor_gestures).
    struct Inputs {
        std::uint64_t geometryRevision = 0;
        std::uint64_t structureChanges = 0;
        Camera camera;
        std::vector<Light> lights;
        std::vector<Material> materials;
        Precision precision = Precision::Float;
        bool operator==(const Inputs&) const = default;
    };
    Inputs inputs() const;

    SceneDocument* doc_;
    FloatRangeCheck check_;
    std::uint64_t structureChanges_ = 0;
    std::optional<Inputs> checked_;  // nothing: not worked out yet
};

}  // namespace whitted::ui
