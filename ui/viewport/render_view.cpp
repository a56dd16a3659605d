#include "viewport/render_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "camera/camera_control.h"
#include "camera/view_move.h"
#include "document/scene_document.h"

namespace whitted::ui {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kClickSlop = 4;           // pixels a press may move and still be a click
constexpr double kKeyOrbit = kPi / 36;  // 5 degrees per arrow key
constexpr double kKeyWalk = 0.05;       // of the distance to look_at per fly mode's W/A/S/D/Q/E

struct CameraActionEntry {
    const char* name;
    QString text;
    QList<QKeySequence> keys;
    std::function<void()> run;
    // Reset, Frame, Move, Scale, Box Select and Fly Mode also sit in the View
    // menu, so they work from anywhere.
    Qt::ShortcutContext context = Qt::WidgetShortcut;
    bool walk = false;  // a fly mode key: enabled in fly mode alone
};

QAction* addCameraAction(QWidget* view, const CameraActionEntry& e) {
    auto* action = new QAction(e.text, view);
    action->setObjectName(QLatin1String(e.name));
    action->setShortcuts(e.keys);
    action->setShortcutContext(e.context);
    QObject::connect(action, &QAction::triggered, view, e.run);
    view->addAction(action);
    return action;
}

}  // namespace

RenderView::RenderView(SceneDocument* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);  // the name of what is under the cursor
    setMinimumSize(160, 120);
    setAttribute(Qt::WA_OpaquePaintEvent);
    buildCameraActions();
    // The overlay follows the camera at once; the picture follows when rendered.
    connect(doc_, &SceneDocument::sceneChanged, this, qOverload<>(&QWidget::update));
    connect(doc_->selection(), &SceneSelection::changed, this, qOverload<>(&QWidget::update));
}

void RenderView::setFrame(const QImage& image, QSizeF shown) {
    frame_ = image;
    frameShown_ = QRectF(QPointF(0, 0), shown.isEmpty() ? QSizeF(image.size()) : shown);
    update();
}

void RenderView::setHomeCamera(const Camera& camera) {
    home_ = camera;
    pivot_.reset();
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
    p.drawImage(QRectF(imageRect()), frame_, frameShown_);
    overlay_.geometryRevision = doc_->geometryRevision();
    paintViewOverlay(p, doc_->scene(), imageRect(), *doc_->selection(), overlay_);
}

void RenderView::moveCamera(const QString& text, const Camera& camera, EditRun run) {
    doc_->edit(
        text, [&](Scene& s) { s.camera = camera; }, nullptr, run);
}

std::optional<Vec3> RenderView::surfaceAt(const QPointF& pos) const {
    const QRect r = imageRect();
    if (!r.contains(pos.toPoint())) return std::nullopt;
    const QPointF image = imagePoint(doc_->scene(), r, pos);
    const auto pick = pickSurface(doc_->scene(), image.x(), image.y());
    if (!pick) return std::nullopt;
    return pick->point;
}

QPair<ItemKind, int> RenderView::itemAt(const QPointF& pos) const {
    const QRect r = imageRect();
    const Scene& s = doc_->scene();
    if (!r.contains(pos.toPoint())) return {ItemKind::Sphere, -1};
    if (const int light = lightMarkerAt(s, r, pos); light >= 0) return {ItemKind::Light, light};
    const QPointF image = imagePoint(s, r, pos);
    return {ItemKind::Sphere, pickSphere(s, image.x(), image.y()).value_or(-1)};
}

Vec3 RenderView::keyPivot() const {
    if (pivot_) return *pivot_;
    const QRect r = imageRect();
    return surfaceAt(QPointF(r.center()) + QPointF(0.5, 0.5)).value_or(doc_->scene().camera.lookAt);
}

void RenderView::updateHover(const QPoint& pos) {
    const auto [kind, index] = itemAt(pos);
    const QString text =
        index < 0 ? QString()
                  : tr("%1 (%2)").arg(itemName(doc_->scene(), kind, index),
                                      kind == ItemKind::Light ? tr("light") : tr("sphere"));
    if (text == overlay_.hoverText && (text.isEmpty() || pos == overlay_.hoverPos)) return;
    overlay_.hoverText = text;
    overlay_.hoverPos = pos;
    update();
}

void RenderView::leaveEvent(QEvent*) {
    pointer_ = {-1, -1};
    overlay_.hoverText.clear();
    update();
}

void RenderView::mousePressEvent(QMouseEvent* e) {
    setFocus();
    if (move_) {
        // Its release is then no click: dragButton_ stays empty.
        if (!move_->byDrag)
            finishMove(e->button() == Qt::LeftButton);
        else if (e->button() == Qt::RightButton)
            finishMove(false);
        return;
    }
    if (boxWaiting_ && e->button() != Qt::LeftButton) {
        boxWaiting_ = false;
        emit moveMessage({});
        return;
    }
    if (dragButton_ != Qt::NoButton) return;
    dragButton_ = e->button();
    pressPos_ = lastPos_ = e->position().toPoint();
    dragging_ = false;
    // Alt+drag on a selected item moves the selection at once.
    if (e->button() == Qt::LeftButton && e->modifiers().testFlag(Qt::AltModifier)) {
        const auto [kind, index] = itemAt(e->position());
        if (doc_->selection()->contains(kind, index) && beginGesture(Gesture::Move, true))
            dragButton_ = Qt::NoButton;
    }
}

void RenderView::mouseMoveEvent(QMouseEvent* e) {
    const QPoint pos = e->position().toPoint();
    pointer_ = pos;
    if (move_) {
        move_->pointer = pos;
        move_->snap = e->modifiers().testFlag(Qt::ControlModifier);
        move_->drop = e->modifiers().testFlag(Qt::ShiftModifier);
        applyMove();
        return;
    }
    if (dragButton_ == Qt::NoButton) {
        updateHover(pos);
        return;
    }
    if (boxWaiting_ && dragButton_ == Qt::LeftButton) {
        overlay_.box = QRect(pressPos_, pos).normalized();
        update();
        return;
    }
    if (!dragging_) {
        if ((pos - pressPos_).manhattanLength() < kClickSlop) return;
        dragging_ = true;
        overlay_.hoverText.clear();
        const bool orbiting = dragButton_ == Qt::LeftButton;
        if (orbiting) {
            // Turn about what the user grabbed; the background grabs the last pivot.
            pivot_ = surfaceAt(pressPos_).value_or(keyPivot());
            overlay_.pivot = pivot_;
        }
        doc_->beginGesture(orbiting ? tr("Orbit camera") : tr("Pan camera"));
    }
    const QPoint delta = pos - lastPos_;
    lastPos_ = pos;
    const double h = std::max(1, imageRect().height());
    const Camera& c = doc_->scene().camera;
    if (dragButton_ == Qt::LeftButton) {
        // A drag across the image's height turns the camera half way round;
        // up raises the eye and left takes it left, as the arrow keys do.
        moveCamera(tr("Orbit camera"),
                   orbitAbout(c, *pivot_, -delta.x() * kPi / h, -delta.y() * kPi / h),
                   EditRun::Separate);
    } else {
        // The scene point under the cursor stays under it at look_at's depth.
        const double scale = 2.0 * std::tan(c.vfovDegrees * kPi / 360.0) / h;
        pivot_.reset();
        moveCamera(tr("Pan camera"), pan(c, -delta.x() * scale, delta.y() * scale),
                   EditRun::Separate);
    }
}

void RenderView::mouseReleaseEvent(QMouseEvent* e) {
    if (move_ && move_->byDrag && e->button() == Qt::LeftButton) return finishMove(true);
    if (e->button() != dragButton_) return;
    dragButton_ = Qt::NoButton;
    if (boxWaiting_ && e->button() == Qt::LeftButton) {
        boxWaiting_ = false;
        const QRect box = std::exchange(overlay_.box, QRect());
        emit moveMessage({});
        update();
        if (!box.isEmpty()) boxSelect(box, e->modifiers().testFlag(Qt::ShiftModifier));
        return;
    }
    if (dragging_) {
        dragging_ = false;
        overlay_.pivot.reset();
        update();
        doc_->endGesture();
        return;
    }
    if (e->button() != Qt::LeftButton) return;
    if (e->modifiers().testFlag(Qt::ControlModifier)) return inspectPixel(e->position());
    clickSelect(e->position(), e->modifiers().testFlag(Qt::ShiftModifier));
}

void RenderView::inspectPixel(const QPointF& pos) {
    const QRect r = imageRect();
    if (!r.contains(pos.toPoint())) return;
    const Scene& scene = doc_->scene();
    const QPointF image = imagePoint(scene, r, pos);
    emit pixelInspected(QPoint(std::clamp(int(image.x()), 0, scene.render.width - 1),
                               std::clamp(int(image.y()), 0, scene.render.height - 1)));
}

void RenderView::setInspectedRays(std::vector<DrawnRay> rays, int highlighted) {
    overlay_.rays = std::move(rays);
    overlay_.highlightedRay = highlighted;
    update();
}

void RenderView::wheelEvent(QWheelEvent* e) {
    const double steps = e->angleDelta().y() / 120.0;
    if (steps == 0) return;
    // Towards what is under the cursor, which stays under it; over the
    // background, towards the pivot the keys would turn about.
    const Vec3 target = surfaceAt(e->position()).value_or(keyPivot());
    moveCamera(tr("Dolly camera"), dollyToward(doc_->scene().camera, target, std::pow(0.9, steps)));
    e->accept();
}

void RenderView::resetCamera() {
    pivot_.reset();
    moveCamera(tr("Reset camera"), home_, EditRun::Separate);
}

void RenderView::frameSelectedSphere() {
    const Scene& s = doc_->scene();
    const int selected = doc_->selection()->active();
    if (doc_->selection()->kind() != ItemKind::Sphere || selected < 0 ||
        selected >= int(s.spheres.size()))
        return;
    const Sphere& sp = s.spheres[selected];
    pivot_ = sp.center;
    moveCamera(tr("Frame %1").arg(QString::fromStdString(sp.name)),
               frameSphere(s.camera, sp.center, sp.radius), EditRun::Separate);
}

std::optional<Vec3> RenderView::restingSpotUnderPointer(double radius) const {
    const Scene& s = doc_->scene();
    const QRect r = imageRect();
    if (!r.contains(pointer_)) return std::nullopt;
    const QPointF image = imagePoint(s, r, pointer_);
    const auto pick = pickSurface(s, image.x(), image.y());
    if (!pick) return std::nullopt;
    return restingCentre(s.spheres[pick->sphere], pick->point, radius);
}

bool RenderView::event(QEvent* e) {
    // During a gesture or a box every key is its own (X, a digit, Escape), not
    // a shortcut's; in fly mode the walk keys and Escape are.
    if (e->type() == QEvent::ShortcutOverride) {
        const int key = static_cast<QKeyEvent*>(e)->key();
        static const QList<int> flyKeys = {Qt::Key_W, Qt::Key_A, Qt::Key_S,     Qt::Key_D,
                                           Qt::Key_Q, Qt::Key_E, Qt::Key_Escape};
        if (move_ || (boxWaiting_ && key == Qt::Key_Escape) || (flying_ && flyKeys.contains(key))) {
            e->accept();
            return true;
        }
    }
    return QWidget::event(e);
}

void RenderView::keyPressEvent(QKeyEvent* e) {
    if (move_) return gestureKey(e);
    if (boxWaiting_ && e->key() == Qt::Key_Escape) {
        boxWaiting_ = false;
        overlay_.box = QRect();
        emit moveMessage({});
        return update();
    }
    if (flying_) return flyKey(e);
    QWidget::keyPressEvent(e);
}

void RenderView::keyReleaseEvent(QKeyEvent* e) {
    if (move_ && (e->key() == Qt::Key_Control || e->key() == Qt::Key_Shift)) {
        (e->key() == Qt::Key_Control ? move_->snap : move_->drop) = false;
        applyMove();
        return;
    }
    QWidget::keyReleaseEvent(e);
}

void RenderView::buildCameraActions() {
    // Each action calls the camera code itself: never a synthetic key event,
    // which would come back to the same shortcut (it overflowed the stack).
    auto move = [this](QString text, std::function<Camera(const Camera&)> f) {
        return [this, text, f] { moveCamera(text, f(doc_->scene().camera)); };
    };
    auto turn = [this](double yaw, double pitch) {
        return [this, yaw, pitch] {
            const Vec3 pivot = keyPivot();
            pivot_ = pivot;  // a run of presses keeps turning about the same point
            moveCamera(tr("Orbit camera"), orbitAbout(doc_->scene().camera, pivot, yaw, pitch));
        };
    };
    auto walkBy = [this](double right, double up, double forward) {
        return [this, right, up, forward] {
            pivot_.reset();
            moveCamera(tr("Move camera"), walk(doc_->scene().camera, right, up, forward));
        };
    };
    const std::vector<CameraActionEntry> entries = {
        {"orbitLeft", tr("Orbit Left"), {Qt::Key_Left}, turn(kKeyOrbit, 0)},
        {"orbitRight", tr("Orbit Right"), {Qt::Key_Right}, turn(-kKeyOrbit, 0)},
        {"orbitUp", tr("Orbit Up"), {Qt::Key_Up}, turn(0, kKeyOrbit)},
        {"orbitDown", tr("Orbit Down"), {Qt::Key_Down}, turn(0, -kKeyOrbit)},
        {"walkForward", tr("Fly Forward"), {Qt::Key_W}, walkBy(0, 0, kKeyWalk), {}, true},
        {"walkBack", tr("Fly Back"), {Qt::Key_S}, walkBy(0, 0, -kKeyWalk), {}, true},
        {"walkLeft", tr("Fly Left"), {Qt::Key_A}, walkBy(-kKeyWalk, 0, 0), {}, true},
        {"walkRight", tr("Fly Right"), {Qt::Key_D}, walkBy(kKeyWalk, 0, 0), {}, true},
        {"walkUp", tr("Rise"), {Qt::Key_E}, walkBy(0, kKeyWalk, 0), {}, true},
        {"walkDown", tr("Sink"), {Qt::Key_Q}, walkBy(0, -kKeyWalk, 0), {}, true},
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
        {"moveSelected",
         tr("Move Selected"),
         {Qt::Key_G},
         [this] { startMove(); },
         Qt::WindowShortcut},
        {"scaleSelected",
         tr("Scale Selected Spheres"),
         {Qt::Key_S},
         [this] { startScale(); },
         Qt::WindowShortcut},
        {"boxSelect",
         tr("Box Select"),
         {Qt::Key_B},
         [this] { startBoxSelect(); },
         Qt::WindowShortcut},
        {"flyMode",
         tr("Fly Mode"),
         // Shift+` arrives as ~ with or without Shift, by keyboard layout.
         {QKeySequence(Qt::SHIFT | Qt::Key_QuoteLeft), QKeySequence(Qt::SHIFT | Qt::Key_AsciiTilde),
          QKeySequence(Qt::Key_AsciiTilde)},
         [this] { setFlying(!flying_); },
         Qt::WindowShortcut},
        {"frameSelected",
         tr("Frame Selected Sphere"),
         {Qt::Key_F},
         [this] { frameSelectedSphere(); },
         Qt::WindowShortcut},
    };
    for (const CameraActionEntry& e : entries) {
        QAction* action = addCameraAction(this, e);
        cameraActions_.push_back(action);
        if (!e.walk) continue;
        action->setEnabled(false);
        walkActions_.push_back(action);
    }
}

QList<QPair<QString, QString>> RenderView::mouseControls() {
    return {
        {tr("Left drag"), tr("Orbit the camera about the point where the drag starts")},
        {tr("Right or middle drag"), tr("Pan the camera")},
        {tr("Wheel"), tr("Move the camera nearer to or farther from what is under the cursor")},
        {tr("Click"), tr("Select the sphere or light under the cursor")},
        {tr("Shift+click"), tr("Add it to the selection, or take it out")},
        {tr("Ctrl+click"),
         tr("Show the rays that make the pixel's colour (the Ray Tree dock, drawn over the "
            "picture)")},
        {tr("B, then drag"),
         tr("Select the spheres (or lights) inside the box; Shift: add to the selection")},
        {tr("G, then move"), tr("Move the selected spheres or lights with the pointer")},
        {tr("Alt+drag on a selected sphere or light"), tr("Move the selection; let go to keep it")},
        {tr("X, Y or Z while moving"), tr("Move along that axis only; again: freely")},
        {tr("A number while moving"), tr("Move by exactly that much (G X 2 Enter)")},
        {tr("Ctrl while moving"),
         tr("Snap the move to the snap step (View > Snap Step; %1 unless set)").arg(kMoveGrid)},
        {tr("Shift while moving"),
         tr("Drop the sphere onto what is under the pointer: on the floor, or touching a ball")},
        {tr("S, then move"),
         tr("Scale the selected spheres' radii: away from their middle grows them")},
        {tr("A number while scaling"), tr("Scale by exactly that factor (S 2 Enter)")},
        {tr("Click or Enter while moving or scaling"), tr("Keep it, one undo step")},
        {tr("Esc or right click while moving or scaling"), tr("Put it back where it was")},
        {tr("W/A/S/D/E/Q in fly mode (Shift+`)"),
         tr("Fly forward, left, back, right, up, down; Esc leaves fly mode")},
        {tr("Hover"), tr("Show the name of the sphere or light under the cursor")}};
}

}  // namespace whitted::ui
