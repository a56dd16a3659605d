#include "image/image_error.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "base/printed.h"
#include "image/image_compare.h"
#include "image/srgb.h"

namespace whitted {

double psnrFromMse(double mse, double peak) {
    if (mse == 0.0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(peak * peak / mse);
}

std::string psnrText(double db) {
    if (std::isinf(db)) return "\u221e dB";
    return printed("%.1f dB", db);
}

ErrorStats measureError(const Image& image, const Image& reference) {
    double sumLinear = 0.0, sumSrgb = 0.0;
    float largest = 0.0f;
    const int w = reference.width, h = reference.height;
    // A row at a time: the image's as the reference's pixels see it.
    std::vector<float> stretched(image.width != w ? 3 * std::size_t(w) : 0);
    for (int y = 0; y < h; ++y) {
        // The image pixel covering this reference pixel, as a stretched view shows it.
        const int iy = std::min(image.height - 1, int(std::int64_t(y) * image.height / h));
        const float* rowA = image.pixel(0, iy);
        if (image.width != w) {
            for (int x = 0; x < w; ++x) {
                const int ix = std::min(image.width - 1, int(std::int64_t(x) * image.width / w));
                std::copy_n(image.pixel(ix, iy), 3, &stretched[3 * std::size_t(x)]);
            }
            rowA = stretched.data();
        }
        const float* rowB = reference.pixel(0, y);
        for (int x = 0; x < w; ++x) {
            const float* a = rowA + 3 * x;
            const float* b = rowB + 3 * x;
            // A finite pixel equal to its reference adds nothing: probes of
            // two depths are mostly equal, and encoding them was half of
            // planning a simple scene's Preview.
            if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2] && std::isfinite(a[0]) &&
                std::isfinite(a[1]) && std::isfinite(a[2]))
                continue;
            int largestCodes = 0;
            bool finite = true;
            for (int c = 0; c < 3; ++c) {
                const double d = double(a[c]) - double(b[c]);
                const bool channelFinite = std::isfinite(d);
                finite = finite && channelFinite;
                sumLinear += channelFinite ? d * d : 1.0;
                const int d8 = int(srgbEncode8(a[c])) - int(srgbEncode8(b[c]));
                sumSrgb += double(d8) * d8;
                largestCodes = std::max(largestCodes, std::abs(d8));
            }
            // Each code is its encoded value rounded, so the encoded values
            // differ by less than one code more than the codes do: a pixel
            // that cannot beat the largest so far needs no std::pow (most of
            // this function's time, when the planning of a render measures
            // its probes).
            if (!finite || (largestCodes + kCodeRoundingSlack) / 255.0f > largest)
                largest = std::max(largest, displayDifference(a, b));
        }
    }
    const double n = 3.0 * double(w) * double(h);
    ErrorStats e;
    e.rmseLinear = std::sqrt(sumLinear / n);
    e.psnrLinear = psnrFromMse(sumLinear / n, 1.0);
    e.rmseSrgb8 = std::sqrt(sumSrgb / n);
    e.psnrSrgb8 = psnrFromMse(sumSrgb / n, 255.0);
    e.largest = double(largest) * 255.0;
    return e;
}

}  // namespace whitted
