// Renders one sweep point and measures it against the reference renders.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "image/image.h"
#include "scene/scene.h"
#include "sweep_plan.h"

namespace whitted::numerics {

// Display-value thresholds of the error figures (compareImages).
inline constexpr float kOneStep = 1.0f / 255.0f;
inline constexpr float kTwoSteps = 2.0f / 255.0f;

// The unscaled, untranslated base scene rendered once in each precision.
struct References {
    Image doubleImage;  // what every point is compared with
    Image floatImage;   // what float 2^k points must equal bit for bit
};

References renderReferences(const Scene& base, int threads);

struct PointResult {
    SweepPoint point;
    // Why the transformed scene is not a valid scene (a radius that overflowed to
    // infinity or underflowed to 0); then nothing below was measured.
    std::optional<std::string> refused;
    std::size_t pixels = 0;
    std::size_t overOne = 0;    // pixels more than 1/255 from the double reference
    std::size_t overTwo = 0;    // pixels more than 2/255 from it
    float largest = 0.0f;       // largest display difference, in [0, 1]
    std::size_t nonFinite = 0;  // pixels with a NaN or infinite channel
    // Scale2 only: the image equals the same-precision reference bit for bit.
    std::optional<bool> bitIdentical;
    double seconds = 0.0;  // render time

    double fractionOverOne() const { return pixels ? double(overOne) / double(pixels) : 1.0; }
    double fractionOverTwo() const { return pixels ? double(overTwo) / double(pixels) : 1.0; }
};

struct Measurement {
    PointResult result;
    Image image;  // empty when refused
};

// `base` carries the size, depth and samples of every render.
Measurement measurePoint(const Scene& base, const SweepPoint& p, const References& refs,
                         int threads);

}  // namespace whitted::numerics
