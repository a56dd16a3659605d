// A render to a quality planned once for many renders: the regions of one
// picture on a farm (whitted-farm), each a whitted-render --region --plan
// FILE. Planning looks at the whole picture, and costs each region as much as
// the whole (scenes/glass.json at 1920x1080 to Final: about 2.5 s of planning
// against 3.2 s of rendering a sixteenth); read from the file, it costs
// nothing, and every region renders to the same depth and limits.
#pragma once

#include <filesystem>
#include <optional>

#include "analysis/quality_target.h"
#include "scene/scene.h"

namespace whitted {

// The plan as a file (JSON), with the picture's size and precision it was made for.
void writePlanFile(const std::filesystem::path& file, const QualityPlan& plan,
                   const RenderSettings& planned);

// The plan in `file`; std::runtime_error naming the file and what is wrong
// where it is no plan, or one made for another picture size, precision or
// target than `settings` and `target`.
QualityPlan readPlanFile(const std::filesystem::path& file, const RenderSettings& settings,
                         const QualityTarget& target);

// The plan in `file` if there is one, else planQuality()'s, written there
// for the renders that follow.
QualityPlan sharedPlan(const std::filesystem::path& file, const Scene& scene,
                       const QualityTarget& target, int maxSamples, std::optional<int> depth);

}  // namespace whitted
