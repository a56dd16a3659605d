#include "analysis/quality_doubt.h"

#include <algorithm>

#include "image/image_compare.h"
#include "image/image_error.h"

namespace whitted::planning {

DepthError depthError(const Image& image, const Image& reference) {
    const ErrorStats e = measureError(image, reference);
    return {e.rmseSrgb8 * e.rmseSrgb8, e.largest};
}

double codesApart(const float* a, const float* b) {
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) return 0.0;
    return 255.0 * displayDifference(a, b);
}

double codesApartAtMost(const float* a, const float* b) {
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) return 0.0;
    return 255.0 * displayDifferenceAtMost(a, b);
}

namespace {

// What renderPixelsUnder() knows of one of the grid's pixels.
enum class GridPixel : char { Outside, Within, Over, Beside };

// Each grid pixel of `parts`, Over or Within, and for those Within what they
// are apart at most (DepthPair::atMost(), exact where it may be over).
void markOver(const DepthPair& pair, const Doubt& doubt, const std::vector<PixelRect>& parts,
              std::vector<GridPixel>& marks, std::vector<double>& upTo) {
    const int width = pair.shallow.width;
    for (const PixelRect& part : parts)
        for (int y = part.y; y < part.y + part.height; ++y)
            for (int x = part.x; x < part.x + part.width; ++x) {
                DepthPair::Apart apart = pair.atMost(x, y);
                if (pair.over(apart, doubt.codes)) apart = pair.at(x, y);
                const std::size_t i = std::size_t(y) * width + x;
                marks[i] = pair.over(apart, doubt.codes) ? GridPixel::Over : GridPixel::Within;
                upTo[i] = std::max(apart.centres, apart.sampled);
            }
}

// Marks Beside the pixels Within `around` pixels of one Over.
void markBesideOver(int width, int height, int around, std::vector<GridPixel>& marks) {
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (marks[std::size_t(y) * width + x] != GridPixel::Over) continue;
            for (int ny = std::max(0, y - around); ny <= std::min(height - 1, y + around); ++ny)
                for (int nx = std::max(0, x - around); nx <= std::min(width - 1, x + around);
                     ++nx) {
                    GridPixel& mark = marks[std::size_t(ny) * width + nx];
                    if (mark == GridPixel::Within) mark = GridPixel::Beside;
                }
        }
}

}  // namespace

RenderPixels renderPixelsUnder(const DepthPair& pair, const Doubt& doubt, int width, int height,
                               const std::vector<PixelRect>& within) {
    const Image& grid = pair.shallow;
    const double across = double(width) / grid.width, down = double(height) / grid.height;
    std::vector<GridPixel> marks(std::size_t(grid.width) * grid.height, GridPixel::Outside);
    std::vector<double> upTo(marks.size(), 0.0);
    markOver(pair, doubt,
             within.empty() ? std::vector<PixelRect>{{0, 0, grid.width, grid.height}} : within,
             marks, upTo);
    if (doubt.around > 0) markBesideOver(grid.width, grid.height, doubt.around, marks);
    RenderPixels under;
    for (int py = 0; py < grid.height; ++py) {
        const int y0 = int(py * down), y1 = int((py + 1) * down);
        int runStart = -1;
        for (int px = 0; px <= grid.width; ++px) {
            const std::size_t i = std::size_t(py) * grid.width + px;
            const bool inDoubt =
                px < grid.width && (marks[i] == GridPixel::Over || marks[i] == GridPixel::Beside);
            if (inDoubt) {
                if (runStart < 0) runStart = px;
                continue;
            }
            // What it is at most would change the largest: then what it is.
            if (px < grid.width && marks[i] == GridPixel::Within &&
                upTo[i] > under.largestElsewhere) {
                const DepthPair::Apart apart = pair.at(px, py);
                under.largestElsewhere =
                    std::max({under.largestElsewhere, apart.centres, apart.sampled});
            }
            if (runStart < 0) continue;
            const int x0 = int(runStart * across), x1 = int(px * across);
            runStart = -1;
            if (x1 == x0 || y1 == y0) continue;
            under.rects.push_back({x0, y0, x1 - x0, y1 - y0});
            under.count += std::size_t(x1 - x0) * (y1 - y0);
        }
    }
    return under;
}

double largestDifference(const Image& a, const Image& b, const std::vector<PixelRect>& rects) {
    double largest = 0.0;
    for (const PixelRect& r : rects)
        for (int y = r.y; y < r.y + r.height; ++y)
            for (int x = r.x; x < r.x + r.width; ++x)
                if (codesApartAtMost(a.pixel(x, y), b.pixel(x, y)) > largest)
                    largest = std::max(largest, codesApart(a.pixel(x, y), b.pixel(x, y)));
    return largest;
}

}  // namespace whitted::planning
