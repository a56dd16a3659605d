#include "render_view.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <cmath>
#include <functional>
#include <vector>

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
    buildCameraActions();
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

void RenderView::resetCamera() {
    moveCamera(tr("Reset camera"), home_);
}

void RenderView::frameSelectedSphere() {
    const Scene& s = doc_->scene();
    if (selectedSphere_ < 0 || selectedSphere_ >= int(s.spheres.size())) return;
    const Sphere& sp = s.spheres[selectedSphere_];
    moveCamera(tr("Frame %1").arg(QString::fromStdString(sp.name)),
               frameSphere(s.camera, sp.center, sp.radius));
}

void RenderView::buildCameraActions() {
    // Each action calls the camera code itself: never a synthetic key event,
    // which would come back to the same shortcut (it overflowed the stack).
    struct Entry {
        const char* name;
        QString text;
        QList<QKeySequence> keys;
        std::function<void()> run;
        // Reset and Frame also sit in the View menu, so they work from anywhere.
        Qt::ShortcutContext context = Qt::WidgetShortcut;
    };
    auto move = [this](QString text, std::function<Camera(const Camera&)> f) {
        return [this, text, f] { moveCamera(text, f(doc_->scene().camera)); };
    };
    const QString orbitText = tr("Orbit camera"), walkText = tr("Move camera");
    const std::vector<Entry> entries = {
        {"orbitLeft",
         tr("Orbit Left"),
         {Qt::Key_Left},
         move(orbitText, [](const Camera& c) { return orbit(c, kKeyOrbit, 0); })},
        {"orbitRight",
         tr("Orbit Right"),
         {Qt::Key_Right},
         move(orbitText, [](const Camera& c) { return orbit(c, -kKeyOrbit, 0); })},
        {"orbitUp",
         tr("Orbit Up"),
         {Qt::Key_Up},
         move(orbitText, [](const Camera& c) { return orbit(c, 0, kKeyOrbit); })},
        {"orbitDown",
         tr("Orbit Down"),
         {Qt::Key_Down},
         move(orbitText, [](const Camera& c) { return orbit(c, 0, -kKeyOrbit); })},
        {"walkForward",
         tr("Walk Forward"),
         {Qt::Key_W},
         move(walkText, [](const Camera& c) { return walk(c, 0, 0, kKeyWalk); })},
        {"walkBack",
         tr("Walk Back"),
         {Qt::Key_S},
         move(walkText, [](const Camera& c) { return walk(c, 0, 0, -kKeyWalk); })},
        {"walkLeft",
         tr("Walk Left"),
         {Qt::Key_A},
         move(walkText, [](const Camera& c) { return walk(c, -kKeyWalk, 0, 0); })},
        {"walkRight",
         tr("Walk Right"),
         {Qt::Key_D},
         move(walkText, [](const Camera& c) { return walk(c, kKeyWalk, 0, 0); })},
        {"walkUp",
         tr("Rise"),
         {Qt::Key_E},
         move(walkText, [](const Camera& c) { return walk(c, 0, kKeyWalk, 0); })},
        {"walkDown",
         tr("Sink"),
         {Qt::Key_Q},
         move(walkText, [](const Camera& c) { return walk(c, 0, -kKeyWalk, 0); })},
        {"zoomIn",
         tr("Zoom In"),
         {Qt::Key_Plus, Qt::Key_Equal},
         move(tr("Zoom"), [](const Camera& c) { return zoom(c, 0.9); })},
        {"zoomOut",
         tr("Zoom Out"),
         {Qt::Key_Minus},
         move(tr("Zoom"), [](const Camera& c) { return zoom(c, 1 / 0.9); })},
        {"resetCamera",
         tr("Reset Camera"),
         {Qt::Key_Home},
         [this] { resetCamera(); },
         Qt::WindowShortcut},
        {"frameSelected",
         tr("Frame Selected Sphere"),
         {Qt::Key_F},
         [this] { frameSelectedSphere(); },
         Qt::WindowShortcut},
    };
    for (const Entry& e : entries) {
        auto* action = new QAction(e.text, this);
        action->setObjectName(QLatin1String(e.name));
        action->setShortcuts(e.keys);
        action->setShortcutContext(e.context);
        connect(action, &QAction::triggered, this, e.run);
        addAction(action);
        cameraActions_.push_back(action);
    }
}

QList<QPair<QString, QString>> RenderView::mouseControls() {
    return {{tr("Left drag"), tr("Orbit the camera")},
            {tr("Right or middle drag"), tr("Pan the camera")},
            {tr("Wheel"), tr("Move the camera nearer or farther (dolly)")},
            {tr("Click"), tr("Select the sphere under the cursor")}};
}

}  // namespace whitted::ui
