// The sweep's results as docs/numerics.md (for people) and numerics.csv (for
// programs). Both are pure text builders; the caller writes the files.
#pragma once

#include <string>
#include <vector>

#include "measure.h"
#include "ranges.h"

namespace whitted::numerics {

// The pictures of one failing point, paths relative to the Markdown file.
struct Picture {
    PointResult result;
    std::string side;       // where it lies, e.g. "first failure above the range"
    std::string imageFile;  // the render
    std::string heatFile;   // its heat map against the reference
};

struct ReportContext {
    std::string regenerate;   // the command that rewrites the report, as Markdown
    std::string sceneName;    // as the reader knows it, e.g. "scenes/seed.json"
    RenderSettings settings;  // size, depth and samples of every render
    int threads = 1;
    bool quick = false;         // the reduced sweep
    std::string referenceFile;  // the double reference render, relative to the report
    std::string csvFile;        // relative to the report
};

std::string markdownReport(const ReportContext& context, const std::vector<PointResult>& results,
                           const std::vector<RangeSummary>& ranges,
                           const std::vector<Picture>& pictures);

// One header line, then one line per point in sweep order.
std::string csvReport(const std::vector<PointResult>& results);

}  // namespace whitted::numerics
