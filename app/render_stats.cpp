#include "render_stats.h"

#include <cstdint>
#include <string>
#include <vector>

#include "render_quality.h"
#include "tracer/kernel_dispatch.h"

namespace whitted {

double cameraRaysPerPixel(const RenderSettings& r, const RenderResult& result) {
    return double(result.rays.camera) / (double(r.width) * r.height);
}

namespace {

// How many pixels were cut 0, 1, ... maxLevels times.
std::vector<long long> pixelsAtEachDepth(const SubdivisionLevels& map, int maxLevels) {
    std::vector<long long> count(maxLevels + 1, 0);
    for (std::uint8_t level : map.levels) ++count[level];
    return count;
}

}  // namespace

nlohmann::ordered_json renderStats(const RenderSettings& r, const RenderResult& result,
                                   const std::optional<QualityPlan>& plan,
                                   const std::optional<Whitted1980Sampling>& whitted1980) {
    const RayCounts& rays = result.rays;
    nlohmann::ordered_json j;
    j["width"] = r.width;
    j["height"] = r.height;
    j["samples_per_pixel"] = r.samplesPerPixel;
    j["max_depth"] = r.maxDepth;
    j["precision"] = std::string(precisionName(r.precision));
    j["threads"] = result.threads;
    j["kernel"] = activeKernelName();
    j["seconds"] = result.seconds;
    // Beside the wall time: on a shared machine the two part when other
    // programs take the cores, and the CPU time is what the tracing cost.
    j["cpu_seconds"] = result.tilesCpuSeconds;
    // How many lights' shadow rays went by a light buffer (light_buffer.h).
    j["light_buffers"] = result.lightBuffers;
    j["rays"] = {{"camera", rays.camera},
                 {"shadow", rays.shadow},
                 {"reflection", rays.reflection},
                 {"refraction", rays.refraction},
                 {"total", rays.total()}};
    j["mrays_per_second"] = result.seconds > 0 ? rays.total() / result.seconds / 1e6 : 0.0;
    if (plan && result.adaptive) {
        j["samples_per_pixel"] = result.adaptive->meanSamples;
        j["quality"] = qualityJson(*plan, *result.adaptive);
    }
    if (whitted1980) {
        j.erase("samples_per_pixel");
        j["sampler"] = {{"name", "whitted1980"},
                        {"threshold", whitted1980->threshold},
                        {"subdivisions", whitted1980->maxLevels},
                        {"camera_rays_per_pixel", cameraRaysPerPixel(r, result)},
                        {"pixels_at_each_depth",
                         pixelsAtEachDepth(result.subdivision, whitted1980->maxLevels)}};
    }
    return j;
}

}  // namespace whitted
