// Form rows editing materials' finish: all of them on the material page, the
// main ones (colour, reflectivity, transparency, index of refraction) on the
// sphere page, where they edit the selected spheres' materials in place. They
// show the first material's values ("mixed" where the others differ) and set
// them all.
#pragma once

#include <functional>
#include <vector>

#include <QString>

#include "document/scene_document.h"

class QFormLayout;
class QWidget;

namespace whitted::ui {

class ColorButton;
class DoubleField;
struct DoubleFieldSpec;

class MaterialRows {
  public:
    using Targets = std::function<std::vector<int>(const Scene&)>;  // the materials' indices
    using TextFn = std::function<QString(const QString& what)>;     // undo text of a change
    enum class Extent { Main, All };

    // Adds the rows to `form`; widgets are named `prefix` + "Diffuse", "Reflectivity", ...
    MaterialRows(SceneDocument* doc, QWidget* owner, QFormLayout* form, Extent extent,
                 const QString& prefix, Targets targets, TextFn text);

    // Shows the first target's values; emits nothing.
    void refresh();

  private:
    DoubleField* scalar(const QString& name, const DoubleFieldSpec& spec, double Material::*member,
                        const QString& what);

    SceneDocument* doc_;
    Targets targets_;
    TextFn text_;
    ColorButton* diffuse_;
    std::vector<DoubleField*> fields_;
};

}  // namespace whitted::ui
