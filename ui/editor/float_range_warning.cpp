#include "editor/float_range_warning.h"

#include <QStyle>

#include "analysis/float_range.h"
#include "document/scene_document.h"

namespace whitted::ui {

std::optional<QString> floatRangeWarningText(const Scene& scene, const FloatRangeCheck& check) {
    if (scene.render.precision != Precision::Float) return std::nullopt;
    const std::optional<std::string> reason = check(scene);
    if (!reason) return std::nullopt;
    return QObject::tr("Scene lies outside float's measured range: %1. Switch to double")
        .arg(QString::fromStdString(*reason));
}

FloatRangeWarning::FloatRangeWarning(SceneDocument* doc, FloatRangeCheck check, QWidget* parent)
    : QPushButton(parent), doc_(doc), check_(check ? std::move(check) : floatRangeProblem) {
    setObjectName(QStringLiteral("floatRangeWarning"));
    setFlat(true);
    setCursor(Qt::PointingHandCursor);
    setIcon(style()->standardIcon(QStyle::SP_MessageBoxWarning));
    setToolTip(tr("Click to render this scene in double precision (undoable)"));
    connect(this, &QPushButton::clicked, this, &FloatRangeWarning::switchToDouble);
    // The document emits structureChanged before sceneChanged: counted first.
    connect(doc_, &SceneDocument::structureChanged, this, [this] { ++structureChanges_; });
    connect(doc_, &SceneDocument::sceneChanged, this, &FloatRangeWarning::refresh);
    connect(doc_, &SceneDocument::gestureEnded, this, &FloatRangeWarning::refresh);
    refresh();
}

FloatRangeWarning::Inputs FloatRangeWarning::inputs() const {
    const Scene& scene = doc_->scene();
    return {doc_->geometryRevision(), structureChanges_,     scene.camera, scene.lights,
            scene.materials,          scene.render.precision};
}

void FloatRangeWarning::refresh() {
    // The check reads every sphere: a million took 8 ms of each pointer move
    // of a drag. It is made once the drag ends.
    if (doc_->inGesture()) return;
    Inputs now = inputs();
    if (checked_ == now) return;
    checked_ = std::move(now);
    const std::optional<QString> text = floatRangeWarningText(doc_->scene(), check_);
    setText(text.value_or(QString()));
    // Without a parent a shown widget would be a window of its own.
    setVisible(text.has_value() && parentWidget());
}

void FloatRangeWarning::switchToDouble() {
    doc_->edit(tr("Switch to double precision"),
               [](Scene& s) { s.render.precision = Precision::Double; });
}

}  // namespace whitted::ui
