// Form rows editing one material's finish: all of them on the material page,
// the main ones (colour, reflectivity, transparency, index of refraction) on
// the sphere page, where they edit the sphere's material in place.
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
    using Locate = std::function<int(const Scene&)>;             // the material's index, or -1
    using TextFn = std::function<QString(const QString& what)>;  // undo text of a change
    enum class Extent { Main, All };

    // Adds the rows to `form`; widgets are named `prefix` + "Diffuse", "Reflectivity", ...
    MaterialRows(SceneDocument* doc, QWidget* owner, QFormLayout* form, Extent extent,
                 const QString& prefix, Locate locate, TextFn text);

    // Shows the located material's values; emits nothing.
    void refresh();

  private:
    DoubleField* scalar(const QString& name, const DoubleFieldSpec& spec, double Material::*member,
                        const QString& what);

    SceneDocument* doc_;
    Locate locate_;
    TextFn text_;
    ColorButton* diffuse_;
    std::vector<DoubleField*> fields_;
};

}  // namespace whitted::ui
