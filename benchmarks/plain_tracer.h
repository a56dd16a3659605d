// A plain scalar Whitted tracer, as a textbook or tinyraytracer writes it: one
// ray at a time, the b^2 - 4ac quadratic, a fixed 1e-4 offset for secondary
// rays, std::pow, rows shared among threads. It is a yardstick for the
// benchmarks only, so that our speed can be stated as a ratio measured in the
// same run on a noisy machine; it is not correct at the extremes our tracer
// handles (it speckles on the seed floor in float) and nothing else uses it.
#pragma once

#include "image/image.h"
#include "scene/scene.h"

namespace whitted::bench {

// Renders scene.render.width x height, one sample per pixel, in T = float or
// double, on `threads` threads. Returns the number of rays traced.
template <typename T>
unsigned long long renderPlain(const Scene& scene, int threads, Image& out);

}  // namespace whitted::bench
