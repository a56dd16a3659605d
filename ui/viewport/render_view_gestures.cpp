// RenderView's gestures on the selection: moving (G, Alt+drag), scaling (S),
// selecting by click and box (B), and fly mode's keys. The camera's mouse
// and keys are in render_view.cpp.
#include <QKeyEvent>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "camera/camera_control.h"
#include "camera/view_move.h"
#include "camera/view_projection.h"
#include "viewport/render_view.h"

namespace whitted::ui {

namespace {

Vec3 itemPosition(const Scene& s, ItemKind kind, int index) {
    return kind == ItemKind::Sphere ? s.spheres[index].center : s.lights[index].position;
}

// "blue ball" for one item, "3 spheres" for more.
QString selectionName(const Scene& s, ItemKind kind, const std::vector<int>& indices) {
    if (indices.size() == 1) return itemName(s, kind, indices.front());
    return countedNoun(int(indices.size()), kind);
}

}  // namespace

bool RenderView::startMove() {
    return beginGesture(Gesture::Move, false);
}

bool RenderView::startScale() {
    return beginGesture(Gesture::Scale, false);
}

bool RenderView::beginGesture(Gesture gesture, bool byDrag) {
    const Scene& s = doc_->scene();
    const SceneSelection& selection = *doc_->selection();
    const ItemKind kind = selection.kind();
    if (move_ || (dragButton_ != Qt::NoButton && !byDrag) || kind == ItemKind::Material ||
        selection.empty() || (gesture == Gesture::Scale && kind != ItemKind::Sphere))
        return false;
    ItemMove m{};
    m.gesture = gesture;
    m.kind = kind;
    m.indices = selection.indices();
    m.byDrag = byDrag;
    for (int i : m.indices) {
        if (i >= itemCount(s, kind)) return false;
        m.starts.push_back(itemPosition(s, kind, i));
        if (kind == ItemKind::Sphere) m.radii.push_back(s.spheres[i].radius);
    }
    m.anchor = itemPosition(s, kind, selection.active());
    // The pointer grabs where it is; started from the menu, outside the view,
    // it grabs the active item's centre.
    const QRect r = imageRect();
    m.pointer = rect().contains(pointer_)
                    ? pointer_
                    : widgetPoint(s, r, m.anchor).value_or(r.center()).toPoint();
    m.grabbed = m.pointer;
    m.from = imagePoint(s, r, m.pointer);
    m.depth = moveDepth(m);
    // A scale's middle: the mean of the centres, where the pointer's distance counts from.
    Vec3 mean(0.0);
    for (const Vec3& p : m.starts) mean += p / double(m.starts.size());
    m.middle = widgetPoint(s, r, mean).value_or(QPointF(r.center()));
    move_ = std::move(m);
    boxWaiting_ = false;
    overlay_.hoverText.clear();
    setFocus();
    emit moveMessage(moveText());
    update();
    return true;
}

// The pointer moves things in the plane facing the camera through the active
// item's centre; but through the point it grabbed on a selected sphere larger
// than that point's distance from the eye, such as a floor: the floor's centre
// lies 100,000 units away, where a pixel is some fifty units.
Vec3 RenderView::moveDepth(const ItemMove& m) const {
    if (m.kind != ItemKind::Sphere || !imageRect().contains(m.pointer)) return m.anchor;
    const Scene& s = doc_->scene();
    const auto pick = pickSurface(s, m.from.x(), m.from.y());
    if (!pick || !std::binary_search(m.indices.begin(), m.indices.end(), pick->sphere))
        return m.anchor;
    const bool huge = s.spheres[pick->sphere].radius > glm::length(pick->point - s.camera.position);
    return huge ? pick->point : m.anchor;
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
    if (m.drop)
        if (const auto offset = dropOffset()) return *offset;
    const Scene& s = doc_->scene();
    const QPointF to = imagePoint(s, imageRect(), m.pointer);
    const Vec3 offset = viewMoveOffset(s.camera, s.render.width, s.render.height, m.depth,
                                       {m.from.x(), m.from.y()}, {to.x(), to.y()}, m.axis);
    return m.snap ? snapToGrid(offset, moveGrid_) : offset;
}

// Shift during a sphere's move: the active sphere rests on the surface under
// the pointer (looking through the spheres that move), the others keep their
// places beside it. Nothing when the pointer sees only the sky.
std::optional<Vec3> RenderView::dropOffset() const {
    const ItemMove& m = *move_;
    const Scene& s = doc_->scene();
    const QRect r = imageRect();
    if (m.kind != ItemKind::Sphere || !r.contains(m.pointer)) return std::nullopt;
    const QPointF image = imagePoint(s, r, m.pointer);
    const auto pick = pickSurface(s, image.x(), image.y(), m.indices);
    if (!pick) return std::nullopt;
    const int active = doc_->selection()->active();
    const auto k = std::lower_bound(m.indices.begin(), m.indices.end(), active) - m.indices.begin();
    return restingCentre(s.spheres[pick->sphere], pick->point, m.radii[k]) - m.anchor;
}

double RenderView::scaleFactor() const {
    const ItemMove& m = *move_;
    if (!m.typed.isEmpty()) {
        bool number = false;
        const double factor = m.typed.toDouble(&number);
        return number && factor > 0 ? factor : 1.0;
    }
    const QPointF grabbed = m.grabbed - m.middle;
    const QPointF now = QPointF(m.pointer) - m.middle;
    const double from = std::hypot(grabbed.x(), grabbed.y());
    const double factor = from > 1 ? std::hypot(now.x(), now.y()) / from : 1.0;
    return m.snap ? std::max(kScaleSnap, std::round(factor / kScaleSnap) * kScaleSnap) : factor;
}

void RenderView::setPositions(const ItemMove& m, const std::function<Vec3(int k)>& position) {
    const QString text = moveStepName(m);
    auto at = [&](int index) {
        return static_cast<int>(std::lower_bound(m.indices.begin(), m.indices.end(), index) -
                                m.indices.begin());
    };
    if (m.kind == ItemKind::Sphere)
        doc_->editItems<Sphere>(m.indices, text,
                                [&](Sphere& sp, int i) { sp.center = position(at(i)); });
    else
        doc_->editItems<Light>(m.indices, text,
                               [&](Light& light, int i) { light.position = position(at(i)); });
}

void RenderView::setRadii(const ItemMove& m, const std::function<double(int k)>& radius) {
    auto at = [&](int index) {
        return static_cast<int>(std::lower_bound(m.indices.begin(), m.indices.end(), index) -
                                m.indices.begin());
    };
    doc_->editItems<Sphere>(m.indices, moveStepName(m),
                            [&](Sphere& sp, int i) { sp.radius = radius(at(i)); });
}

void RenderView::putBack(const ItemMove& m) {
    setPositions(m, [&](int k) { return m.starts[k]; });
    if (m.gesture == Gesture::Scale) setRadii(m, [&](int k) { return m.radii[k]; });
}

bool RenderView::changedSinceStart(const ItemMove& m) const {
    const Scene& s = doc_->scene();
    for (std::size_t k = 0; k < m.indices.size(); ++k) {
        if (itemPosition(s, m.kind, m.indices[k]) != m.starts[k]) return true;
        if (m.kind == ItemKind::Sphere && s.spheres[m.indices[k]].radius != m.radii[k]) return true;
    }
    return false;
}

void RenderView::applyMove() {
    ItemMove& m = *move_;
    const bool scale = m.gesture == Gesture::Scale;
    const Vec3 offset = scale ? Vec3(0.0) : moveOffset();
    const double factor = scale ? scaleFactor() : 1.0;
    if (!m.recorded) {
        // No step for a gesture that never changed anything.
        if (offset == Vec3(0.0) && factor == 1.0) {
            emit moveMessage(moveText());
            return;
        }
        doc_->beginGesture(moveStepName(m));
        m.recorded = true;
    }
    if (scale)
        setRadii(m, [&](int k) { return m.radii[k] * factor; });
    else
        setPositions(m, [&](int k) { return m.starts[k] + offset; });
    emit moveMessage(moveText());
}

void RenderView::finishMove(bool keep) {
    const ItemMove m = *move_;
    move_.reset();
    if (m.recorded) {
        // Kept where it started, a gesture leaves no step either.
        if (keep && changedSinceStart(m)) {
            doc_->endGesture();
        } else {
            putBack(m);
            doc_->discardGesture();
        }
    }
    emit moveMessage({});
    emit moveFinished();
    update();
}

QString RenderView::moveStepName(const ItemMove& m) const {
    const QString what = selectionName(doc_->scene(), m.kind, m.indices);
    return m.gesture == Gesture::Scale ? tr("Scale %1").arg(what) : tr("Move %1").arg(what);
}

QString RenderView::moveText() const {
    const ItemMove& m = *move_;
    const QString typed = m.typed.isEmpty() ? QString() : tr(" (typed %1)").arg(m.typed);
    if (m.gesture == Gesture::Scale)
        return tr("%1 by %2%3 · type a factor · Ctrl: steps of %4 · click: keep · Esc: cancel")
            .arg(moveStepName(m))
            .arg(scaleFactor(), 0, 'g', 4)
            .arg(typed)
            .arg(kScaleSnap);
    static const char* const kAxes[] = {"X", "Y", "Z"};
    const Vec3 offset = moveOffset();
    const QString along = m.axis ? tr(" along %1").arg(QLatin1String(kAxes[*m.axis])) : QString();
    const QString drop =
        m.kind == ItemKind::Sphere ? tr(" · Shift: onto the surface pointed at") : QString();
    return tr("%1 by %2, %3, %4%5%6 · X/Y/Z: axis · type a distance · Ctrl: snap to %7%8 · "
              "click: keep · Esc: cancel")
        .arg(moveStepName(m))
        .arg(offset.x, 0, 'g', 4)
        .arg(offset.y, 0, 'g', 4)
        .arg(offset.z, 0, 'g', 4)
        .arg(along, typed)
        .arg(moveGrid_)
        .arg(drop);
}

void RenderView::gestureKey(QKeyEvent* e) {
    ItemMove& m = *move_;
    const QString text = e->text();
    switch (e->key()) {
        case Qt::Key_Escape:
            return finishMove(false);
        case Qt::Key_Return:
        case Qt::Key_Enter:
            return finishMove(true);
        case Qt::Key_X:
        case Qt::Key_Y:
        case Qt::Key_Z: {
            if (m.gesture == Gesture::Scale) return;
            const int axis = e->key() - Qt::Key_X;
            m.axis = m.axis == axis ? std::nullopt : std::optional<int>(axis);
            break;
        }
        case Qt::Key_Backspace:
            m.typed.chop(1);
            break;
        case Qt::Key_Minus:
            if (m.gesture == Gesture::Scale) return;
            // As in Blender: the sign of what is typed, at any time.
            m.typed = m.typed.startsWith('-') ? m.typed.mid(1) : QStringLiteral("-") + m.typed;
            break;
        case Qt::Key_Control:
            m.snap = true;
            break;
        case Qt::Key_Shift:
            m.drop = true;
            break;
        default:
            if (text.size() != 1 || !(text[0].isDigit() || text[0] == '.')) return;
            m.typed += text;
    }
    applyMove();
}

void RenderView::clickSelect(const QPointF& pos, bool toggle) {
    const auto [kind, index] = itemAt(pos);
    if (toggle)
        doc_->selection()->toggle(kind, index);
    else if (index >= 0)
        doc_->selection()->selectOne(kind, index);
}

void RenderView::startBoxSelect() {
    if (move_) return;
    boxWaiting_ = true;
    setFocus();
    emit moveMessage(
        tr("Drag a box to select the spheres and lights inside it "
           "(Shift: add to the selection); Esc or right click: cancel"));
}

// What lies inside: spheres whose centres project into the box (Blender's
// rule for objects), lights whose markers do. Spheres win over lights when
// both are inside, a selection being of one kind.
void RenderView::boxSelect(const QRect& box, bool add) {
    const Scene& s = doc_->scene();
    const QRect r = imageRect();
    const QPointF a = imagePoint(s, r, box.topLeft()), b = imagePoint(s, r, box.bottomRight());
    std::vector<int> spheres = spheresCentredIn(s.camera, s.render.width, s.render.height,
                                                s.spheres, {a.x(), a.y()}, {b.x(), b.y()});
    std::vector<int> lights;
    for (int i = 0; i < int(s.lights.size()); ++i)
        if (const auto p = widgetPoint(s, r, s.lights[i].position); p && box.contains(p->toPoint()))
            lights.push_back(i);
    const ItemKind kind = spheres.empty() && !lights.empty() ? ItemKind::Light : ItemKind::Sphere;
    std::vector<int> chosen = kind == ItemKind::Sphere ? spheres : lights;
    SceneSelection* selection = doc_->selection();
    if (add && selection->kind() == kind)
        chosen.insert(chosen.end(), selection->indices().begin(), selection->indices().end());
    selection->set(kind, std::move(chosen), add ? selection->active() : -1);
}

void RenderView::setFlying(bool on) {
    if (on == flying_) return;
    flying_ = on;
    for (QAction* a : walkActions_) a->setEnabled(on);
    emit moveMessage(on ? tr("Fly mode: W/S forward and back, A/D left and right, E/Q up and "
                             "down; Esc or Shift+` to leave")
                        : QString());
}

void RenderView::flyKey(QKeyEvent* e) {
    if (e->key() == Qt::Key_Escape) return setFlying(false);
    for (QAction* a : walkActions_)
        if (a->shortcut() == QKeySequence(e->key())) return a->trigger();
}

}  // namespace whitted::ui
