// docs/tradeoff.md's section on Whitted's 1980 sampling: bench_whitted1980's
// measurements of it against our fixed and adaptive sampling, a table and a
// plot a scene, and the verdict the figures give.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <QString>

#include "plot/scatter_plot.h"

namespace whitted::tradeoff {

// One render of bench_whitted1980's CSV.
struct SamplerRow {
    std::string scene, sampler, setting;  // sampler: fixed, adaptive or whitted1980
    int width = 0, height = 0;
    double cameraRaysPerPixel = 0, raysPerPixel = 0, seconds = 0, psnrDb = 0, largestCodes = 0;
};

// Throws std::runtime_error naming the file and line when it is not such a CSV.
std::vector<SamplerRow> readSamplerCsv(const std::filesystem::path& file);

// PSNR against milliseconds or against camera rays a pixel, one line a
// sampler, for one scene's rows.
enum class SamplerAxis { Time, CameraRays };
ui::PlotSpec samplerPlot(const QString& scene, const std::vector<SamplerRow>& rows,
                         SamplerAxis axis);

// The section; `plots` holds each scene's plot files relative to the report,
// without their ending (STEM.png against time, STEM-rays.png against camera
// rays), in the order the scenes first appear in `rows`.
std::string samplerSection(const std::vector<SamplerRow>& rows, const std::string& csvFile,
                           const std::vector<std::string>& plots);

// The scenes in the order they first appear.
std::vector<std::string> samplerScenes(const std::vector<SamplerRow>& rows);
// The rows of one scene, in their order.
std::vector<SamplerRow> samplerRowsOf(const std::vector<SamplerRow>& rows,
                                      const std::string& scene);

}  // namespace whitted::tradeoff
