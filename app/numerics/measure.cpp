#include "measure.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "image/image_compare.h"
#include "scene/scene_io.h"
#include "tracer/renderer.h"

namespace whitted::numerics {

namespace {

RenderResult renderOnce(const Scene& scene, int threads) {
    RenderOptions options = oneShotOptions();  // the time is the image's, not a preview's
    options.threads = threads;
    return render(scene, options);
}

// Bitwise, so that a NaN equals itself and -0 differs from +0.
bool bitIdentical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

std::size_t countNonFinite(const Image& image) {
    std::size_t count = 0;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
        if (!std::isfinite(image.rgb[i]) || !std::isfinite(image.rgb[i + 1]) ||
            !std::isfinite(image.rgb[i + 2]))
            ++count;
    return count;
}

}  // namespace

References renderReferences(const Scene& base, int threads) {
    Scene s = base;
    s.render.precision = Precision::Double;
    References refs;
    refs.doubleImage = renderOnce(s, threads).image;
    s.render.precision = Precision::Float;
    refs.floatImage = renderOnce(s, threads).image;
    return refs;
}

Measurement measurePoint(const Scene& base, const SweepPoint& p, const References& refs,
                         int threads) {
    Measurement m;
    m.result.point = p;
    const Scene scene = sceneAt(base, p);
    if (auto problem = validateScene(scene)) {
        m.result.refused = problem->jsonPath + ": " + problem->reason;
        return m;
    }
    RenderResult rendered = renderOnce(scene, threads);
    m.image = std::move(rendered.image);
    PointResult& r = m.result;
    r.seconds = rendered.seconds;
    const ImageDifference one = compareImages(m.image, refs.doubleImage, kOneStep);
    const ImageDifference two = compareImages(m.image, refs.doubleImage, kTwoSteps);
    r.pixels = one.pixels;
    r.overOne = one.over;
    r.overTwo = two.over;
    r.largest = one.largest;
    r.nonFinite = countNonFinite(m.image);
    if (p.kind == SweepKind::Scale2) {
        const Image& same = p.precision == Precision::Float ? refs.floatImage : refs.doubleImage;
        r.bitIdentical = bitIdentical(m.image, same);
    }
    return m;
}

}  // namespace whitted::numerics
