#include "viewport/ray_tree_overlay.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <QLineF>
#include <QPainter>

#include "tracer/camera.h"
#include "viewport/view_overlay.h"

namespace whitted::ui {

namespace {

void collect(const RayTreeNode& node, double skyReach, std::vector<DrawnRay>& rays) {
    DrawnRay& ray = rays.emplace_back();
    ray.kind = node.kind;
    ray.from = node.origin;
    // A shadow ray's t is the distance to its light, which it reaches or not.
    ray.hitSomething = node.hit >= 0 || node.kind == RayTreeNode::Kind::Shadow;
    ray.to = node.origin + node.direction * (ray.hitSomething ? node.t : skyReach);
    ray.transmittance = node.transmittance;
    for (const RayTreeNode& child : node.children) collect(child, skyReach, rays);
}

// The part of segment a-b in front of the eye: a ray that passes behind the
// camera (a reflection back past it, the camera ray itself, which starts at
// the eye) is cut where it crosses a plane just in front of the eye.
std::optional<std::pair<Vec3, Vec3>> inFrontOfEye(const CameraBasis<double>& eye, double near,
                                                  Vec3 a, Vec3 b) {
    const double da = glm::dot(a - eye.origin, eye.forward) - near;
    const double db = glm::dot(b - eye.origin, eye.forward) - near;
    if (da < 0 && db < 0) return std::nullopt;
    if (da < 0) a += (b - a) * (da / (da - db));
    if (db < 0) b += (a - b) * (db / (db - da));
    return std::pair{a, b};
}

// Liang-Barsky: the part of `line` inside `box`. A segment towards the sky
// can project thousands of widths away, which the raster engine draws badly.
std::optional<QLineF> clipped(QLineF line, const QRectF& box) {
    double t0 = 0, t1 = 1;
    const double dx = line.dx(), dy = line.dy();
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {line.x1() - box.left(), box.right() - line.x1(), line.y1() - box.top(),
                         box.bottom() - line.y1()};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0) {
            if (q[k] < 0) return std::nullopt;
            continue;
        }
        const double t = q[k] / p[k];
        if (p[k] < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
    }
    if (t0 > t1) return std::nullopt;
    return QLineF(line.pointAt(t0), line.pointAt(t1));
}

void paintRay(QPainter& painter, const Scene& scene, const QRect& r, const CameraBasis<double>& eye,
              double near, const DrawnRay& ray, bool highlighted) {
    const auto part = inFrontOfEye(eye, near, ray.from, ray.to);
    if (!part) return;
    const auto a = widgetPoint(scene, r, part->first);
    const auto b = widgetPoint(scene, r, part->second);
    if (!a || !b) return;
    const auto line = clipped(QLineF(*a, *b), QRectF(r).adjusted(-20, -20, 20, 20));
    if (!line) return;
    const QColor colour = rayColour(ray.kind);
    const Qt::PenStyle style = ray.kind == RayTreeNode::Kind::Shadow && ray.transmittance <= 0
                                   ? Qt::DashLine
                                   : Qt::SolidLine;
    // A dark line under the coloured one, as under the selection's outline.
    painter.setPen(QPen(QColor(0, 0, 0, 170), highlighted ? 7 : 4, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(*line);
    if (highlighted) {
        painter.setPen(QPen(Qt::white, 5, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(*line);
    }
    painter.setPen(QPen(colour, highlighted ? 3 : 2, style, Qt::RoundCap));
    painter.drawLine(*line);
    if (ray.hitSomething && ray.kind != RayTreeNode::Kind::Shadow && b->x() == line->x2() &&
        b->y() == line->y2()) {
        painter.setBrush(colour);
        painter.setPen(QPen(QColor(0, 0, 0, 170), 1));
        painter.drawEllipse(*b, 3, 3);
    }
}

}  // namespace

std::vector<DrawnRay> drawnRays(const RayTreeNode& root) {
    std::vector<DrawnRay> rays;
    // Far enough that a ray into the sky ends near where its direction vanishes.
    const double skyReach = 1e3 * std::max(1.0, root.hit >= 0 ? root.t : 1.0);
    collect(root, skyReach, rays);
    return rays;
}

QColor rayColour(RayTreeNode::Kind kind) {
    switch (kind) {
        case RayTreeNode::Kind::Camera:
            return QColor(255, 255, 255);
        case RayTreeNode::Kind::Reflection:
            return QColor(40, 200, 255);
        case RayTreeNode::Kind::Refraction:
            return QColor(90, 230, 110);
        case RayTreeNode::Kind::Shadow:
            return QColor(255, 215, 0);
    }
    return Qt::white;
}

void paintRayTree(QPainter& painter, const Scene& scene, const QRect& imageRect,
                  const std::vector<DrawnRay>& rays, int highlighted) {
    if (rays.empty()) return;
    const CameraBasis<double> eye =
        makeCameraBasis<double>(scene.camera, scene.render.width, scene.render.height);
    const double near = 1e-4 * glm::length(scene.camera.lookAt - scene.camera.position);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    for (std::size_t i = 0; i < rays.size(); ++i)
        if (int(i) != highlighted) paintRay(painter, scene, imageRect, eye, near, rays[i], false);
    if (highlighted >= 0 && highlighted < int(rays.size()))
        paintRay(painter, scene, imageRect, eye, near, rays[highlighted], true);
    // The camera ray is seen end on: a ring at the pixel it leaves through.
    if (const auto at = widgetPoint(
            scene, imageRect, rays.front().from + (rays.front().to - rays.front().from) * 1e-3)) {
        painter.setBrush(Qt::NoBrush);
        for (const auto& [colour, width] :
             {std::pair{QColor(0, 0, 0, 170), 4.0}, {rayColour(RayTreeNode::Kind::Camera), 2.0}}) {
            painter.setPen(QPen(colour, width));
            painter.drawEllipse(*at, 7, 7);
        }
    }
    painter.restore();
}

}  // namespace whitted::ui
