// Where two renders of a picture at two depths part, pixel by pixel: the
// pixels of the render that a depth's check must judge with samples, because
// a grid's pixel (the probe's or the picture's) may hold a sliver of light
// over the limit there (quality_depth.cpp).
#pragma once

#include <cstddef>
#include <vector>

#include "image/image.h"

namespace whitted::planning {

// A depth's error against a deeper one: the 8-bit MSE and the largest error.
struct DepthError {
    double mse = 0.0, largest = 0.0;
};
DepthError depthError(const Image& image, const Image& reference);

// 8-bit codes apart; most pixels of two depths are equal, and skip the sRGB curve.
double codesApart(const float* a, const float* b);

// At least codesApart(a, b), from the 8-bit codes (displayDifferenceAtMost()):
// the pictures' checks need the exact difference only where it may be over
// a limit or the largest so far, and its std::pow was most of their loops.
double codesApartAtMost(const float* a, const float* b);

// Two renders of one grid (the probe's or the picture's) at two depths: at
// the pixels' centres, and where the picture is also checked with several
// samples a pixel, those too.
struct DepthPair {
    const Image& shallow;
    const Image& deep;
    const Image* shallowSampled = nullptr;
    const Image* deepSampled = nullptr;
    int samples = 1;

    struct Apart {
        double centres = 0.0, sampled = 0.0;  // codes
    };
    Apart at(int x, int y) const { return apart(x, y, codesApart); }
    // At least at(x, y), without std::pow (codesApartAtMost()).
    Apart atMost(int x, int y) const { return apart(x, y, codesApartAtMost); }
    // Whether a pixel may hold a sliver over `limit`: its centres are over it,
    // or its samples' mean over 1/n of it (one of n samples sees a sliver,
    // and their mean shows 1/n of it).
    bool over(const Apart& a, double limit) const {
        return a.centres > limit || samples * a.sampled > limit;
    }

  private:
    Apart apart(int x, int y, double (*codes)(const float*, const float*)) const {
        Apart a{codes(shallow.pixel(x, y), deep.pixel(x, y))};
        if (shallowSampled)
            a.sampled = codes(shallowSampled->pixel(x, y), deepSampled->pixel(x, y));
        return a;
    }
};

// Pixels of the render, as renderPixelsUnder() finds them.
struct RenderPixels {
    std::vector<PixelRect> rects;
    std::size_t count = 0;
    double largestElsewhere = 0.0;
};

// Which of the grid's pixels renderPixelsUnder() finds in doubt: those that
// may hold a sliver over `codes` (DepthPair::over()), and those within
// `around` pixels of one.
struct Doubt {
    double codes;
    int around = 0;
};

// The render's pixels under the grid's pixels in doubt (Doubt), as
// rectangles (one for each run of such grid pixels along a row), and the
// largest difference of the grid's other pixels. Each of the render's
// pixels lies under one grid pixel: the grid pixel's edges rounded down to
// the render's. Only the grid's pixels `within`, if given.
RenderPixels renderPixelsUnder(const DepthPair& pair, const Doubt& doubt, int width, int height,
                               const std::vector<PixelRect>& within = {});

// The largest codesApart() of `a` and `b` over `rects`.
double largestDifference(const Image& a, const Image& b, const std::vector<PixelRect>& rects);

}  // namespace whitted::planning
