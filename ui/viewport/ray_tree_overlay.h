// The rays of an inspected pixel drawn over the picture (the Ray Tree dock's
// tree): each ray a segment from its origin to what it hit, or towards the sky
// when it hit nothing, coloured by its kind; the camera ray, which the eye
// sees end on, a ring at the pixel. One ray may be highlighted: the dock's
// selected row.
#pragma once

#include <vector>

#include <QColor>
#include <QRect>

#include "analysis/pixel_ray_tree.h"
#include "scene/scene.h"

class QPainter;

namespace whitted::ui {

struct DrawnRay {
    RayTreeNode::Kind kind = RayTreeNode::Kind::Camera;
    Vec3 from{0.0};
    Vec3 to{0.0};
    bool hitSomething = false;   // false: it leaves the scene towards the sky
    double transmittance = 1.0;  // a shadow ray's: drawn dashed when nothing gets through
};

// The tree's rays in the order the dock lists them (depth first, each ray
// before its children).
std::vector<DrawnRay> drawnRays(const RayTreeNode& root);

// The colour each kind of ray is drawn in, and listed with in the dock.
QColor rayColour(RayTreeNode::Kind kind);

// Draws `rays` as `scene`'s camera sees them into `imageRect`; `highlighted`
// (an index into rays, or -1) over the others, wider and outlined in white.
void paintRayTree(QPainter& painter, const Scene& scene, const QRect& imageRect,
                  const std::vector<DrawnRay>& rays, int highlighted);

}  // namespace whitted::ui
