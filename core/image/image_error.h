// Error of a render against a reference image: RMSE and PSNR of the linear image
// and of the 8-bit sRGB image a user sees, and the largest per-pixel difference
// (displayDifference, core/image/image_compare.h).
#pragma once

#include <string>

#include "image/image.h"

namespace whitted {

struct ErrorStats {
    double rmseLinear = 0.0;  // over every channel of the linear images
    double psnrLinear = 0.0;  // dB, peak 1.0; +infinity for identical images
    double rmseSrgb8 = 0.0;   // over every channel of the 8-bit sRGB codes, in codes
    double psnrSrgb8 = 0.0;   // dB, peak 255; +infinity for identical images
    double largest = 0.0;     // largest displayDifference() of a pixel, in 8-bit steps
};

// `image` may be smaller than `reference` (a render at a lower resolution
// scale): it is then compared as a viewer shows it, each reference pixel
// against the image pixel covering it (nearest neighbour).
ErrorStats measureError(const Image& image, const Image& reference);

// PSNR in dB of a mean squared error against the peak (255 for 8-bit codes,
// 1 for linear values); +infinity for no error at all, where the ratio has no
// bound. JSON has no infinity: nlohmann writes it as null.
double psnrFromMse(double mse, double peak = 255.0);

// "35.2 dB", or "∞ dB" for no error at all.
std::string psnrText(double db);

}  // namespace whitted
