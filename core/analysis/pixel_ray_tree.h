// The ray tree of one pixel, as Whitted's 1980 paper draws it: the camera ray,
// then at every hit a shadow ray towards each light and the refracted and
// reflected rays, each with what it hit, the weight its path passes on and
// what it adds to the pixel. It is the tree of a one-sample render (the
// pixel's centre) at the scene's size, depth and precision, and its numbers
// are the renderer's: every ray's radiance is traced by the render's own
// kernel, so the root's is the rendered pixel, bit for bit.
#pragma once

#include <vector>

#include "scene/scene.h"

namespace whitted {

struct RayTreeNode {
    enum class Kind { Camera, Reflection, Refraction, Shadow };
    Kind kind = Kind::Camera;
    Vec3 origin{0.0};     // in scene coordinates
    Vec3 direction{0.0};  // unit length
    int depth = 0;        // 0 for the camera ray; a shadow ray has its hit's
    // The product of the reflectivities and transparencies from the camera ray
    // to this one (a shadow ray: its hit's).
    double weight = 1.0;
    int hit = -1;                          // the sphere it hit (its index), -1 for none
    double t = 0.0;                        // the distance to that hit; a shadow ray's: to its light
    bool entering = false;                 // it hit its sphere from outside
    bool totalInternalReflection = false;  // at a transparent hit: no refracted ray
    // What this ray adds to the pixel: its weight times its own shading (the
    // ambient and the lights at its hit, or the background where it hits
    // nothing). A shadow ray's share is in its hit's.
    Vec3 contribution{0.0};
    Vec3 radiance{0.0};          // along this ray: its contribution and those below it, unweighted
    int light = -1;              // a shadow ray's light (its index)
    double transmittance = 1.0;  // a shadow ray's: what reaches the light, 0 to 1
    // A hit at the maximum depth whose material reflects or transmits: the
    // rays it does not spawn would add `pastDepth` (traced kPastDepthLevels further).
    bool cutOff = false;
    Vec3 pastDepth{0.0};
    std::vector<RayTreeNode> children;  // shadow rays first, then refraction, then reflection
};

inline constexpr int kPastDepthLevels = 16;

struct PixelRayTree {
    int x = 0, y = 0;
    // The pixel of a one-sample render, linear, as its image holds it (float).
    Vec3 value{0.0};
    RayTreeNode root;
};

// Pixel (x, y) of the scene's picture; the scene must be valid. Throws
// std::out_of_range when the pixel lies outside the picture.
PixelRayTree pixelRayTree(const Scene& scene, int x, int y);
// The same traced in `precision` rather than the scene's own: float against
// double without a copy of the scene.
PixelRayTree pixelRayTree(const Scene& scene, int x, int y, Precision precision);

// The sum of every node's contribution: the pixel's value but for rounding.
Vec3 sumOfContributions(const RayTreeNode& node);

}  // namespace whitted
