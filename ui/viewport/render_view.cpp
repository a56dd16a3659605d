#include "viewport/render_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

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
constexpr double kKeyWalk = 0.05;       // of the distance to look_at per W/A/S/D/Q/E

struct CameraActionEntry {
    const char* name;
    QString text;
    QList<QKeySequence> keys;
    std::function<void()> run;
    // Reset, Frame and Move also sit in the View menu, so they work from anywhere.
    Qt::ShortcutContext context = Qt::WidgetShortcut;
};

// Where a sphere (its centre) or a light is.
Vec3 itemPosition(const Scene& s, ItemKind kind, int index) {
    return kind == ItemKind::Sphere ? s.spheres[index].center : s.lights[index].position;
}

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

void RenderView::setSelection(ItemKind kind, int index) {
    overlay_.selectedKind = kind;
    overlay_.selectedIndex = index;
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
    p.drawImage(QRectF(imageRect()), frame_, frameShown_);
    paintViewOverlay(p, doc_->scene(), imageRect(), overlay_);
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
        finishMove(e->button() == Qt::LeftButton);
        return;
    }
    if (dragButton_ != Qt::NoButton) return;
    dragButton_ = e->button();
    pressPos_ = lastPos_ = e->position().toPoint();
    dragging_ = false;
}

void RenderView::mouseMoveEvent(QMouseEvent* e) {
    const QPoint pos = e->position().toPoint();
    pointer_ = pos;
    if (move_) {
        move_->pointer = pos;
        move_->snap = e->modifiers().testFlag(Qt::ControlModifier);
        applyMove();
        return;
    }
    if (dragButton_ == Qt::NoButton) {
        updateHover(pos);
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
    if (e->button() != dragButton_) return;
    dragButton_ = Qt::NoButton;
    if (dragging_) {
        dragging_ = false;
        overlay_.pivot.reset();
        update();
        doc_->endGesture();
        return;
    }
    if (e->button() != Qt::LeftButton) return;
    const auto [kind, index] = itemAt(e->position());
    emit picked(kind, index);
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
    const int selected = overlay_.selectedIndex;
    if (overlay_.selectedKind != ItemKind::Sphere || selected < 0 ||
        selected >= int(s.spheres.size()))
        return;
    const Sphere& sp = s.spheres[selected];
    pivot_ = sp.center;
    moveCamera(tr("Frame %1").arg(QString::fromStdString(sp.name)),
               frameSphere(s.camera, sp.center, sp.radius), EditRun::Separate);
}

bool RenderView::startMove() {
    const Scene& s = doc_->scene();
    const ItemKind kind = overlay_.selectedKind;
    const int index = overlay_.selectedIndex;
    if (move_ || dragButton_ != Qt::NoButton || kind == ItemKind::Material || index < 0 ||
        index >= itemCount(s, kind))
        return false;
    const Vec3 start = itemPosition(s, kind, index);
    // The pointer grabs where it is; started from the menu, outside the view,
    // it grabs the item's centre.
    const QRect r = imageRect();
    QPoint pointer = pointer_;
    if (!rect().contains(pointer))
        pointer = widgetPoint(s, r, start).value_or(r.center()).toPoint();
    move_ = ItemMove{kind, index, start, imagePoint(s, r, pointer), pointer, {}, {}, false, false};
    overlay_.hoverText.clear();
    setFocus();
    emit moveMessage(moveText(Vec3(0.0)));
    update();
    return true;
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

Vec3 RenderView::moveOffset() const {
    const ItemMove& m = *move_;
    if (!m.typed.isEmpty()) {
        Vec3 unit(0.0);
        unit[m.axis.value_or(0)] = 1;
        bool number = false;
        const double distance = m.typed.toDouble(&number);
        return number ? unit * distance : Vec3(0.0);
    }
    const Scene& s = doc_->scene();
    const QPointF to = imagePoint(s, imageRect(), m.pointer);
    const Vec3 offset = viewMoveOffset(s.camera, s.render.width, s.render.height, m.start,
                                       {m.from.x(), m.from.y()}, {to.x(), to.y()}, m.axis);
    return m.snap ? snapToGrid(offset, kMoveGrid) : offset;
}

QString RenderView::moveStepName(const ItemMove& m) const {
    return tr("Move %1").arg(itemName(doc_->scene(), m.kind, m.index));
}

void RenderView::setItemPosition(const ItemMove& m, const Vec3& position) {
    const QString text = moveStepName(m);
    if (m.kind == ItemKind::Sphere)
        doc_->editItem<Sphere>(m.index, text, [&](Sphere& sphere) { sphere.center = position; });
    else
        doc_->editItem<Light>(m.index, text, [&](Light& light) { light.position = position; });
}

void RenderView::applyMove() {
    ItemMove& m = *move_;
    const Vec3 offset = moveOffset();
    const Vec3 position = m.start + offset;
    if (!m.recorded) {
        // No step for a move that never moved.
        if (position == m.start) {
            emit moveMessage(moveText(offset));
            return;
        }
        doc_->beginGesture(moveStepName(m));
        m.recorded = true;
    }
    setItemPosition(m, position);
    emit moveMessage(moveText(offset));
}

void RenderView::finishMove(bool keep) {
    const ItemMove m = *move_;
    move_.reset();
    if (m.recorded) {
        const Vec3 now = itemPosition(doc_->scene(), m.kind, m.index);
        // Kept where it started, a move leaves no step either.
        if (keep && now != m.start) {
            doc_->endGesture();
        } else {
            setItemPosition(m, m.start);
            doc_->discardGesture();
        }
    }
    emit moveMessage({});
    emit moveFinished();
    update();
}

QString RenderView::moveText(const Vec3& offset) const {
    const ItemMove& m = *move_;
    static const char* const kAxes[] = {"X", "Y", "Z"};
    const QString along = m.axis ? tr(" along %1").arg(QLatin1String(kAxes[*m.axis])) : QString();
    const QString typed = m.typed.isEmpty() ? QString() : tr(" (typed %1)").arg(m.typed);
    return tr("%1 by %2, %3, %4%5%6. X, Y, Z: along an axis; type a distance; "
              "Ctrl: snap to %7; Enter or click: done; Esc or right click: cancel")
        .arg(moveStepName(m))
        .arg(offset.x, 0, 'g', 4)
        .arg(offset.y, 0, 'g', 4)
        .arg(offset.z, 0, 'g', 4)
        .arg(along, typed)
        .arg(kMoveGrid);
}

bool RenderView::event(QEvent* e) {
    // During a move every key is the move's (X, a digit, Escape), not a shortcut's.
    if (move_ && e->type() == QEvent::ShortcutOverride) {
        e->accept();
        return true;
    }
    return QWidget::event(e);
}

void RenderView::keyPressEvent(QKeyEvent* e) {
    if (!move_) {
        QWidget::keyPressEvent(e);
        return;
    }
    ItemMove& m = *move_;
    const QString text = e->text();
    switch (e->key()) {
        case Qt::Key_Escape:
            finishMove(false);
            return;
        case Qt::Key_Return:
        case Qt::Key_Enter:
            finishMove(true);
            return;
        case Qt::Key_X:
        case Qt::Key_Y:
        case Qt::Key_Z: {
            const int axis = e->key() - Qt::Key_X;
            m.axis = m.axis == axis ? std::nullopt : std::optional<int>(axis);
            break;
        }
        case Qt::Key_Backspace:
            m.typed.chop(1);
            break;
        case Qt::Key_Minus:
            // As in Blender: the sign of what is typed, at any time.
            m.typed = m.typed.startsWith('-') ? m.typed.mid(1) : QStringLiteral("-") + m.typed;
            break;
        case Qt::Key_Control:
            m.snap = true;
            break;
        default:
            if (text.size() != 1 || !(text[0].isDigit() || text[0] == '.')) return;
            m.typed += text;
    }
    applyMove();
}

void RenderView::keyReleaseEvent(QKeyEvent* e) {
    if (move_ && e->key() == Qt::Key_Control) {
        move_->snap = false;
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
        {"walkForward", tr("Walk Forward"), {Qt::Key_W}, walkBy(0, 0, kKeyWalk)},
        {"walkBack", tr("Walk Back"), {Qt::Key_S}, walkBy(0, 0, -kKeyWalk)},
        {"walkLeft", tr("Walk Left"), {Qt::Key_A}, walkBy(-kKeyWalk, 0, 0)},
        {"walkRight", tr("Walk Right"), {Qt::Key_D}, walkBy(kKeyWalk, 0, 0)},
        {"walkUp", tr("Rise"), {Qt::Key_E}, walkBy(0, kKeyWalk, 0)},
        {"walkDown", tr("Sink"), {Qt::Key_Q}, walkBy(0, -kKeyWalk, 0)},
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
        {"frameSelected",
         tr("Frame Selected Sphere"),
         {Qt::Key_F},
         [this] { frameSelectedSphere(); },
         Qt::WindowShortcut},
    };
    for (const CameraActionEntry& e : entries) cameraActions_.push_back(addCameraAction(this, e));
}

QList<QPair<QString, QString>> RenderView::mouseControls() {
    return {{tr("Left drag"), tr("Orbit the camera about the point where the drag starts")},
            {tr("Right or middle drag"), tr("Pan the camera")},
            {tr("Wheel"), tr("Move the camera nearer to or farther from what is under the cursor")},
            {tr("Click"), tr("Select the sphere or light under the cursor")},
            {tr("G, then move"), tr("Move the selected sphere or light with the pointer")},
            {tr("X, Y or Z while moving"), tr("Move along that axis only; again: freely")},
            {tr("A number while moving"), tr("Move by exactly that much (G X 2 Enter)")},
            {tr("Ctrl while moving"), tr("Snap the move to steps of %1").arg(kMoveGrid)},
            {tr("Click or Enter while moving"), tr("Keep the move, one undo step")},
            {tr("Esc or right click while moving"), tr("Put it back where it was")},
            {tr("Hover"), tr("Show the name of the sphere or light under the cursor")}};
}

}  // namespace whitted::ui
