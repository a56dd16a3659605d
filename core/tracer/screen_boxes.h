// Where in the picture camera rays can meet each of a few spheres, so that a
// packet of camera rays tests only the spheres whose box it overlaps. Read by
// every kernel, made once a render by code built with the project's flags, so
// it lives outside the per-ISA namespace (as sphere_set.h).
#pragma once

#include <cstdint>
#include <vector>

#include "tracer/camera.h"
#include "tracer/isa_namespace.h"
#include "tracer/sphere_set.h"

namespace whitted {

// A box of image-plane positions in pixels (x right, y down, as a camera
// sample's i + u and j + v), open-ended where a bound is infinite; empty
// (min > max) for a sphere no camera ray meets.
struct ScreenBox {
    float xMin, xMax, yMin, yMax;
};

// How much wider than a sphere its screen box and its shadow cones
// (shadow_cones.h) are, relative to the sphere's distance and size: a float
// ray direction is off by a few 1e-8 radians and the float sphere test by a
// few 1e-8 of |o - centre| and r, so this is a margin of a hundred times.
// Still narrow enough that the seed's floor, 0.85 below an eye 1e5 from its
// centre, is left out of the sky.
inline constexpr double kSkipWidening = 4e-6;

// The spheres a brute-force packet can skip: at most this many, the first ones.
inline constexpr int kScreenBoxedSpheres = 32;

// The boxes of the first kScreenBoxedSpheres spheres. Each holds the sphere's
// outline widened by far more than the rounding of a camera ray's direction
// and of the sphere test, so that a camera ray outside the box is one the
// sphere test would report as a miss: skipping it changes no pixel.
template <typename T>
std::vector<ScreenBox> sphereScreenBoxes(const CameraBasis<T>& camera, const SphereSet<T>& spheres);

inline namespace WHITTED_ISA_NAMESPACE {

// Bit k set: sphere k's box meets the box [xMin, xMax] x [yMin, yMax]. In
// each kernel's namespace, as the kernel calls it (isa_namespace.h).
inline std::uint32_t spheresInView(const std::vector<ScreenBox>& boxes, float xMin, float xMax,
                                   float yMin, float yMax) {
    std::uint32_t seen = 0;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        const ScreenBox& b = boxes[k];
        if (b.xMin <= xMax && xMin <= b.xMax && b.yMin <= yMax && yMin <= b.yMax) seen |= 1u << k;
    }
    return seen;
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
