// What a render did, as `whitted-render --stats` writes it and the Python
// module's render(return_stats=True) returns it: one JSON object for both.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "analysis/quality_target.h"
#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

// Camera rays a pixel of the picture: 1 for one sample, more where Whitted's
// 1980 sampler cut pixels.
double cameraRaysPerPixel(const RenderSettings& r, const RenderResult& result);

// Size, samples, depth, precision, threads, kernel, seconds, rays by kind and
// Mrays/s; with a plan, what the render to a quality reached; with Whitted's
// 1980 sampling, its settings and how deep it cut.
nlohmann::ordered_json renderStats(const RenderSettings& r, const RenderResult& result,
                                   const std::optional<QualityPlan>& plan,
                                   const std::optional<Whitted1980Sampling>& whitted1980);

}  // namespace whitted
