// ColorButton: swatch, dialog and the sRGB conversions between them.
#include "panels/color_button.h"

#include <cmath>

#include <QColorDialog>
#include <QEvent>
#include <QPainter>
#include <QPixmap>

#include "image/srgb.h"
#include "viewport/image_convert.h"

namespace whitted::ui {

namespace {

QString shortNumber(double v) {
    return QString::number(v, 'g', 3);
}

}  // namespace

ColorButton::ColorButton(QWidget* parent) : QPushButton(parent) {
    setIconSize(QSize(32, 14));
    connect(this, &QPushButton::clicked, this, &ColorButton::pick);
    updateSwatch();
}

void ColorButton::setColor(const Vec3& linear) {
    if (linear == color_) return;
    color_ = linear;
    updateSwatch();
}

void ColorButton::edit(const Vec3& linear) {
    setColor(linear);
    emit colorEdited(color_);
}

void ColorButton::changeEvent(QEvent* event) {
    if (event->type() == QEvent::EnabledChange) updateSwatch();
    QPushButton::changeEvent(event);
}

void ColorButton::pick() {
    const QColor shown = displayColour(color_);
    const QColor picked = QColorDialog::getColor(shown, this, tr("Choose a colour"));
    if (!picked.isValid() || picked.rgb() == shown.rgb()) return;
    // A channel the user left alone keeps its exact value: the dialog's 8 bits
    // would otherwise nudge it (and clamp values above 1) on every pick.
    auto channel = [](int before, int after, double original, float afterF) {
        return before == after ? original : srgbDecode(double(afterF));
    };
    edit(Vec3{channel(shown.red(), picked.red(), color_.x, picked.redF()),
              channel(shown.green(), picked.green(), color_.y, picked.greenF()),
              channel(shown.blue(), picked.blue(), color_.z, picked.blueF())});
}

void ColorButton::updateSwatch() {
    QPixmap swatch(iconSize());
    swatch.fill(Qt::transparent);
    QPainter painter(&swatch);
    painter.setPen(palette().color(QPalette::Mid));
    painter.setBrush(isEnabled() ? displayColour(color_) : palette().color(QPalette::Window));
    painter.drawRect(swatch.rect().adjusted(0, 0, -1, -1));
    painter.end();
    setIcon(QIcon(swatch));
    setText(QStringLiteral("%1, %2, %3")
                .arg(shortNumber(color_.x), shortNumber(color_.y), shortNumber(color_.z)));
    setToolTip(tr("Linear RGB %1; click to choose").arg(text()));
}

}  // namespace whitted::ui
