#include "viewport/view_overlay.h"

#include <algorithm>
#include <cmath>

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>

#include "camera/view_projection.h"
#include "tracer/camera.h"

namespace whitted::ui {

namespace {

constexpr double kMarkerRadius = 6;  // pixels; a click within kMarkerReach selects
constexpr double kMarkerReach = 10;
const QColor kSelection(255, 160, 30);    // one colour for "selected", outline and marker ring
const QColor kAlsoSelected(215, 95, 15);  // the others of a selection, as Blender's darker orange

QPointF toWidget(const Scene& scene, const QRect& r, const ImagePoint& p) {
    return {r.left() + p.x * r.width() / scene.render.width,
            r.top() + p.y * r.height() / scene.render.height};
}

void paintSphereOutline(QPainter& painter, const Scene& scene, const QRect& r, const Sphere& s,
                        const QColor& colour) {
    QPainterPath path;
    for (const auto& piece :
         sphereOutline(scene.camera, scene.render.width, scene.render.height, s.center, s.radius)) {
        path.moveTo(toWidget(scene, r, piece.front()));
        for (const ImagePoint& p : piece) path.lineTo(toWidget(scene, r, p));
    }
    // A dark line under the bright one: visible on the white floor and the black sky alike.
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(0, 0, 0, 160), 4));
    painter.drawPath(path);
    painter.setPen(QPen(colour, 2));
    painter.drawPath(path);
}

const std::vector<ImagePoint>& dotsOf(const Scene& scene, const SceneSelection& selection,
                                      std::uint64_t geometryRevision, SelectionDots& dots) {
    const int w = scene.render.width, h = scene.render.height;
    if (dots.geometryRevision != geometryRevision || dots.width != w || dots.height != h ||
        !(dots.camera == scene.camera) || dots.indices != selection.indices()) {
        dots.points = projectCentres(scene.camera, w, h, scene.spheres, selection.indices());
        dots.camera = scene.camera;
        dots.width = w;
        dots.height = h;
        dots.geometryRevision = geometryRevision;
        dots.indices = selection.indices();
        dots.layer = QImage();
    }
    return dots.points;
}

// The dots, 2 by 2 pixels each, in an image of `size` (the picture's place).
const QImage& dotLayerOf(const Scene& scene, QSize size, SelectionDots& dots) {
    if (dots.layer.size() == size) return dots.layer;
    QImage layer(size, QImage::Format_ARGB32_Premultiplied);
    layer.fill(Qt::transparent);
    const QRgb colour = kAlsoSelected.rgba();  // opaque: premultiplied alike
    const QRect place(QPoint(0, 0), size);
    for (const ImagePoint& at : dots.points) {
        const QPointF p = toWidget(scene, place, at);
        const int x = int(std::floor(p.x())), y = int(std::floor(p.y()));
        for (int row = std::max(y, 0); row < std::min(y + 2, size.height()); ++row) {
            auto* line = reinterpret_cast<QRgb*>(layer.scanLine(row));
            for (int column = std::max(x, 0); column < std::min(x + 2, size.width()); ++column)
                line[column] = colour;
        }
    }
    dots.layer = std::move(layer);
    return dots.layer;
}

void paintSelectedSpheres(QPainter& painter, const Scene& scene, const QRect& r,
                          const SceneSelection& selection, ViewOverlay& overlay) {
    // Indices ascend: the last one says whether all are spheres of this scene.
    if (selection.empty() || selection.indices().back() >= int(scene.spheres.size())) return;
    const int active = selection.active();
    if (selection.count() <= kMostOutlines) {
        for (int i : selection.indices())
            if (i != active) paintSphereOutline(painter, scene, r, scene.spheres[i], kAlsoSelected);
    } else {
        dotsOf(scene, selection, overlay.geometryRevision, overlay.dots);
        painter.drawImage(r.topLeft(), dotLayerOf(scene, r.size(), overlay.dots));
    }
    if (active >= 0) paintSphereOutline(painter, scene, r, scene.spheres[active], kSelection);
}

void paintBox(QPainter& painter, const QRect& box) {
    painter.setBrush(QColor(255, 255, 255, 30));
    painter.setPen(QPen(QColor(0, 0, 0, 160), 1));
    painter.drawRect(box);
    painter.setPen(QPen(Qt::white, 1, Qt::DashLine));
    painter.drawRect(box);
}

// Where a light's marker goes: on the light when the picture shows it, else at
// the picture's edge in the direction the camera would turn to see it (lights
// usually sit outside the frame, and a newcomer must still find them).
struct MarkerPlace {
    QPointF at;
    bool inPicture = true;
    QPointF outward;  // unit, towards the light, when it is outside the picture
};

MarkerPlace lightMarkerPlace(const Scene& scene, const QRect& r, const Vec3& light) {
    if (const auto image =
            projectToImage(scene.camera, scene.render.width, scene.render.height, light)) {
        const QPointF at = toWidget(scene, r, *image);
        if (QRectF(r).contains(at)) return {at, true, {}};
    }
    const CameraBasis<double> b =
        makeCameraBasis<double>(scene.camera, scene.render.width, scene.render.height);
    const Vec3 d = light - b.origin;
    // Image x is right and y down; a light straight behind reads as below.
    QPointF dir(glm::dot(d, b.right), -glm::dot(d, b.up));
    const double length = std::hypot(dir.x(), dir.y());
    dir = length > 0 ? dir / length : QPointF(0, 1);
    const double margin = kMarkerRadius + 10;
    const double halfWidth = std::max(1.0, r.width() / 2.0 - margin);
    const double halfHeight = std::max(1.0, r.height() / 2.0 - margin);
    const double reach = std::min(std::abs(dir.x()) > 0 ? halfWidth / std::abs(dir.x()) : 1e300,
                                  std::abs(dir.y()) > 0 ? halfHeight / std::abs(dir.y()) : 1e300);
    return {QRectF(r).center() + dir * reach, false, dir};
}

void paintLightMarker(QPainter& painter, const MarkerPlace& place, const Light& light,
                      bool selected) {
    const QPointF at = place.at;
    const double brightest = std::max({light.color.r, light.color.g, light.color.b, 1e-9});
    const QColor fill =
        QColor::fromRgbF(float(light.color.r / brightest), float(light.color.g / brightest),
                         float(light.color.b / brightest));
    // Rays in the light's own colour (seen on the dark sky), the disc ringed in
    // black (seen on the white floor), both in the selection colour when selected.
    painter.setPen(QPen(selected ? kSelection : fill, selected ? 2.5 : 1.5));
    for (int k = 0; k < 8; ++k) {  // rays: a sun, the usual sign for a point light
        const double a = k * M_PI / 4;
        const QPointF dir(std::cos(a), std::sin(a));
        painter.drawLine(at + dir * (kMarkerRadius + 2), at + dir * (kMarkerRadius + 5));
    }
    painter.setPen(QPen(selected ? kSelection : QColor(20, 20, 20), selected ? 2.5 : 1.5));
    painter.setBrush(fill);
    painter.drawEllipse(at, kMarkerRadius, kMarkerRadius);
    if (place.inPicture) return;
    // Outside the picture: an arrowhead beyond the rays points the way to the light.
    const QPointF tip = at + place.outward * (kMarkerRadius + 12);
    const QPointF side(-place.outward.y(), place.outward.x());
    const QPointF base = at + place.outward * (kMarkerRadius + 6);
    painter.drawPolygon(QPolygonF{tip, base + side * 4, base - side * 4});
}

void paintPivot(QPainter& painter, const QPointF& at) {
    painter.setBrush(Qt::NoBrush);
    for (const auto& [colour, width] : {std::pair{QColor(0, 0, 0, 160), 3.0}, {Qt::white, 1.5}}) {
        painter.setPen(QPen(colour, width));
        painter.drawEllipse(at, 5, 5);
        painter.drawLine(at - QPointF(9, 0), at + QPointF(9, 0));
        painter.drawLine(at - QPointF(0, 9), at + QPointF(0, 9));
    }
}

void paintHoverLabel(QPainter& painter, const QRect& bounds, const QString& text,
                     const QPoint& at) {
    const QFontMetrics metrics(painter.font());
    QRect box = metrics.boundingRect(text).adjusted(-5, -3, 5, 3);
    box.moveTopLeft(at + QPoint(14, 16));
    // Kept inside the view: flipped to the cursor's other side near an edge.
    if (box.right() > bounds.right()) box.moveRight(at.x() - 6);
    if (box.bottom() > bounds.bottom()) box.moveBottom(at.y() - 6);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(20, 20, 20, 210));
    painter.drawRoundedRect(box, 3, 3);
    painter.setPen(Qt::white);
    painter.drawText(box, Qt::AlignCenter, text);
}

}  // namespace

std::optional<QPointF> widgetPoint(const Scene& scene, const QRect& imageRect, const Vec3& p) {
    const auto image = projectToImage(scene.camera, scene.render.width, scene.render.height, p);
    if (!image) return std::nullopt;
    return toWidget(scene, imageRect, *image);
}

QPointF imagePoint(const Scene& scene, const QRect& imageRect, const QPointF& widget) {
    const QPointF p = widget - QPointF(imageRect.topLeft());
    return {p.x() * scene.render.width / std::max(1, imageRect.width()),
            p.y() * scene.render.height / std::max(1, imageRect.height())};
}

void paintViewOverlay(QPainter& painter, const Scene& scene, const QRect& imageRect,
                      const SceneSelection& selection, ViewOverlay& overlay) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setClipRect(imageRect);
    if (selection.kind() == ItemKind::Sphere)
        paintSelectedSpheres(painter, scene, imageRect, selection, overlay);
    paintRayTree(painter, scene, imageRect, overlay.rays, overlay.highlightedRay);
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const bool isSelected = selection.contains(ItemKind::Light, int(i));
        paintLightMarker(painter, lightMarkerPlace(scene, imageRect, scene.lights[i].position),
                         scene.lights[i], isSelected);
    }
    if (overlay.pivot)
        if (const auto at = widgetPoint(scene, imageRect, *overlay.pivot)) paintPivot(painter, *at);
    if (!overlay.box.isEmpty()) paintBox(painter, overlay.box);
    painter.setClipping(false);
    if (!overlay.hoverText.isEmpty())
        paintHoverLabel(painter, painter.window(), overlay.hoverText, overlay.hoverPos);
    painter.restore();
}

int lightMarkerAt(const Scene& scene, const QRect& imageRect, const QPointF& pos) {
    int nearest = -1;
    double nearestDistance = kMarkerReach;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const QPointF at = lightMarkerPlace(scene, imageRect, scene.lights[i].position).at;
        const double distance = std::hypot(at.x() - pos.x(), at.y() - pos.y());
        if (distance <= nearestDistance) {
            nearest = int(i);
            nearestDistance = distance;
        }
    }
    return nearest;
}

}  // namespace whitted::ui
