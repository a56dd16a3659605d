#include "render_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <cmath>

#include "camera_control.h"
#include "scene_document.h"

namespace whitted::ui {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kClickSlop = 4;           // pixels a press may move and still be a click
constexpr double kKeyOrbit = kPi / 36;  // 5 degrees per arrow key
constexpr double kKeyWalk = 0.05;       // of the distance to look_at per W/A/S/D/Q/E
}  // namespace

RenderView::RenderView(SceneDocument* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setMinimumSize(160, 120);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void RenderView::setFrame(const QImage& image) {
    frame_ = image;
    update();
}

QRect RenderView::imageRect() const {
    const Scene& s = doc_->scene();
    QSize size(s.render.width, s.render.height);
    size.scale(this->size(), Qt::KeepAspectRatio);
    return {QPoint((width() - size.width()) / 2, (height() - size.height()) / 2), size};
}

void RenderView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(45, 45, 48));
    if (frame_.isNull()) return;
    // Scaled while a new frame is on its way: the old image, stretched, beats a blank.
    p.setRenderHint(QPainter::SmoothPixmapTransform, frame_.width() > imageRect().width());
    p.drawImage(imageRect(), frame_);
}

void RenderView::moveCamera(const QString& text, const Camera& camera) {
    doc_->edit(text, [&](Scene& s) { s.camera = camera; });
}

void RenderView::mousePressEvent(QMouseEvent* e) {
    setFocus();
    if (dragButton_ != Qt::NoButton) return;
    dragButton_ = e->button();
    pressPos_ = lastPos_ = e->position().toPoint();
    dragging_ = false;
}

void RenderView::mouseMoveEvent(QMouseEvent* e) {
    if (dragButton_ == Qt::NoButton) return;
    const QPoint pos = e->position().toPoint();
    if (!dragging_) {
        if ((pos - pressPos_).manhattanLength() < kClickSlop) return;
        dragging_ = true;
        doc_->beginGesture(dragButton_ == Qt::LeftButton ? tr("Orbit camera") : tr("Pan camera"));
    }
    const QPoint delta = pos - lastPos_;
    lastPos_ = pos;
    const double h = std::max(1, imageRect().height());
    const Camera& c = doc_->scene().camera;
    if (dragButton_ == Qt::LeftButton) {
        // A drag across the image's height turns the camera half way round.
        moveCamera(tr("Orbit camera"), orbit(c, -delta.x() * kPi / h, delta.y() * kPi / h));
    } else {
        // The scene point under the cursor stays under it at look_at's depth.
        const double scale = 2.0 * std::tan(c.vfovDegrees * kPi / 360.0) / h;
        moveCamera(tr("Pan camera"), pan(c, -delta.x() * scale, delta.y() * scale));
    }
}

void RenderView::mouseReleaseEvent(QMouseEvent* e) {
    if (e->button() != dragButton_) return;
    dragButton_ = Qt::NoButton;
    if (dragging_) {
        dragging_ = false;
        doc_->endGesture();
        return;
    }
    if (e->button() != Qt::LeftButton) return;
    const QRect r = imageRect();
    const QPointF p = e->position() - QPointF(r.topLeft());
    if (p.x() < 0 || p.y() < 0 || p.x() >= r.width() || p.y() >= r.height()) {
        emit spherePicked(-1);
        return;
    }
    const Scene& s = doc_->scene();
    const auto hit =
        pickSphere(s, p.x() * s.render.width / r.width(), p.y() * s.render.height / r.height());
    emit spherePicked(hit ? *hit : -1);
}

void RenderView::wheelEvent(QWheelEvent* e) {
    const double steps = e->angleDelta().y() / 120.0;
    if (steps == 0) return;
    moveCamera(tr("Dolly camera"), dolly(doc_->scene().camera, std::pow(0.9, steps)));
    e->accept();
}

void RenderView::keyPressEvent(QKeyEvent* e) {
    const Camera& c = doc_->scene().camera;
    switch (e->key()) {
        case Qt::Key_Left:
            return moveCamera(tr("Orbit camera"), orbit(c, kKeyOrbit, 0));
        case Qt::Key_Right:
            return moveCamera(tr("Orbit camera"), orbit(c, -kKeyOrbit, 0));
        case Qt::Key_Up:
            return moveCamera(tr("Orbit camera"), orbit(c, 0, kKeyOrbit));
        case Qt::Key_Down:
            return moveCamera(tr("Orbit camera"), orbit(c, 0, -kKeyOrbit));
        case Qt::Key_W:
            return moveCamera(tr("Move camera"), walk(c, 0, 0, kKeyWalk));
        case Qt::Key_S:
            return moveCamera(tr("Move camera"), walk(c, 0, 0, -kKeyWalk));
        case Qt::Key_A:
            return moveCamera(tr("Move camera"), walk(c, -kKeyWalk, 0, 0));
        case Qt::Key_D:
            return moveCamera(tr("Move camera"), walk(c, kKeyWalk, 0, 0));
        case Qt::Key_E:
            return moveCamera(tr("Move camera"), walk(c, 0, kKeyWalk, 0));
        case Qt::Key_Q:
            return moveCamera(tr("Move camera"), walk(c, 0, -kKeyWalk, 0));
        case Qt::Key_Plus:
        case Qt::Key_Equal:
            return moveCamera(tr("Zoom"), zoom(c, 0.9));
        case Qt::Key_Minus:
            return moveCamera(tr("Zoom"), zoom(c, 1 / 0.9));
        case Qt::Key_Home:
            return moveCamera(tr("Reset camera"), home_);
        case Qt::Key_F: {
            const Scene& s = doc_->scene();
            if (selectedSphere_ < 0 || selectedSphere_ >= int(s.spheres.size())) return;
            const Sphere& sp = s.spheres[selectedSphere_];
            return moveCamera(tr("Frame %1").arg(QString::fromStdString(sp.name)),
                              frameSphere(c, sp.center, sp.radius));
        }
        default:
            QWidget::keyPressEvent(e);
    }
}

}  // namespace whitted::ui
