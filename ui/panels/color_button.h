// A push button showing a colour swatch that opens a colour dialog; the scene's
// linear RGB is shown and picked through the sRGB curve, as the GUI shows images (SPEC §5).
#pragma once

#include <QPushButton>

#include "scene/scene.h"

namespace whitted::ui {

class ColorButton : public QPushButton {
    Q_OBJECT
  public:
    explicit ColorButton(QWidget* parent = nullptr);

    // Shows `linear` without emitting colorEdited. Components above 1 are kept;
    // only the swatch and the dialog see them clamped.
    void setColor(const whitted::Vec3& linear);
    whitted::Vec3 color() const { return color_; }

    // As if the user had picked `linear`: sets it and emits colorEdited.
    void edit(const whitted::Vec3& linear);

  signals:
    void colorEdited(const whitted::Vec3& linear);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void pick();
    void updateSwatch();

    whitted::Vec3 color_{0.0, 0.0, 0.0};
};

}  // namespace whitted::ui
