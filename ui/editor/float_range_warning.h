// The status bar's warning that a float scene lies outside the range in which
// float renders were measured to match double ones (core/analysis/float_range.h). It
// names the reason and, clicked, switches the scene to double as one undoable
// edit. Re-evaluated on every change of the scene: edit, undo, redo, open, new.
#pragma once

#include <QPushButton>

#include <functional>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace whitted::ui {

class SceneDocument;

// Why a scene is outside float's measured range, or nothing (core's floatRangeProblem()).
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

    SceneDocument* doc_;
    FloatRangeCheck check_;
};

}  // namespace whitted::ui
