#include "image/image_metadata.h"

#include <sstream>
#include <utility>

namespace whitted {

ImageMetadata makeImageMetadata(const RenderSettings& s, double renderSeconds, std::string software,
                                std::string qualityTarget, std::string qualityReached) {
    ImageMetadata m;
    m.software = std::move(software);
    m.settings = s;
    m.renderSeconds = renderSeconds;
    m.qualityTarget = std::move(qualityTarget);
    m.qualityReached = std::move(qualityReached);
    std::ostringstream d;
    d << "Whitted ray tracer: " << s.width << "x" << s.height << ", ";
    if (m.qualityTarget.empty())
        d << s.samplesPerPixel << " samples per pixel, max depth " << s.maxDepth;
    else
        d << "to a quality, " << qualityLine(m);
    d << ", " << precisionName(s.precision) << " precision, rendered in " << renderSeconds << " s";
    m.description = d.str();
    return m;
}

std::string qualityLine(const ImageMetadata& m) {
    if (m.qualityReached.empty()) return m.qualityTarget;
    return m.qualityTarget + "; " + m.qualityReached;
}

}  // namespace whitted
