#include "image/image_metadata.h"

#include <sstream>
#include <utility>

namespace whitted {

ImageMetadata makeImageMetadata(const RenderSettings& s, double renderSeconds, std::string software,
                                std::string quality) {
    ImageMetadata m;
    m.software = std::move(software);
    m.settings = s;
    m.renderSeconds = renderSeconds;
    m.quality = std::move(quality);
    std::ostringstream d;
    d << "Whitted ray tracer: " << s.width << "x" << s.height << ", ";
    if (m.quality.empty())
        d << s.samplesPerPixel << " samples per pixel, max depth " << s.maxDepth;
    else
        d << "to a quality, " << m.quality;
    d << ", " << precisionName(s.precision) << " precision, rendered in " << renderSeconds << " s";
    m.description = d.str();
    return m;
}

}  // namespace whitted
