// A Whitted tracer built on Intel Embree 3: the peer bench_scaling
// races, never part of the editor or the renderer. Same camera, shading rules
// (SPEC §3, core/tracer/scalar_ray_tree.h), 1 sample per pixel, float. Camera rays go through
// Embree in 16-wide packets (rtcIntersect16); secondary and shadow rays one by
// one (rtcIntersect1, rtcOccluded1 with a filter that multiplies the
// transparencies of the spheres crossed, as our tracer's shadow rays do).
//
// Embree has no exact self-intersection rule like ours: a secondary ray starts
// kEmbreeRayOffset along itself, so the two images agree to a PSNR, not bit for
// bit. Huge spheres such as the floor stay out of Embree and are tested in
// double: a radius of 99999 in Embree's float quadratic would make a bumpy floor.
#pragma once

#include "image/image.h"
#include "scene/scene.h"
#include "tracer/tracer.h"

namespace whitted {

struct EmbreeRun {
    double buildHighMs = 0;    // RTC_BUILD_QUALITY_HIGH, best of three
    double buildMediumMs = 0;  // RTC_BUILD_QUALITY_MEDIUM, best of three
    double renderMs = 0;       // high-quality build and render, wall time
    RayCounts rays;
    Image image;
};

// Renders scene.render.width x height with `threads` threads. Throws
// std::runtime_error when Embree reports an error.
EmbreeRun renderWithEmbree(const Scene& scene, int threads);

}  // namespace whitted
