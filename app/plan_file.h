// A render to a quality planned once for many renders: the regions of one
// picture on a farm (whitted-farm), each a whitted-render --region --plan
// FILE. Planning looks at the whole picture, and costs each region as much as
// the whole (scenes/glass.json at 1920x1080 to Final: about 2.5 s of planning
// against 3.2 s of rendering a sixteenth); read from the file, it costs
// nothing, and every region renders to the same depth and limits.
#pragma once

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "analysis/quality_target.h"
#include "scene/scene.h"

namespace whitted {

// Every field of the plan, under the names --stats gives them in its
// "quality" block; planFromJson() reads them back.
nlohmann::ordered_json planJson(const QualityPlan& plan);
QualityPlan planFromJson(const nlohmann::json& j);

// The plan as a file (JSON), with the scene (its content, picture size and
// precision) it was made for.
void writePlanFile(const std::filesystem::path& file, const QualityPlan& plan, const Scene& scene);

// The plan in `file`; std::runtime_error naming the file and what is wrong
// where it is no plan, or one made for another scene, picture size,
// precision or target than `scene` and `target`.
QualityPlan readPlanFile(const std::filesystem::path& file, const Scene& scene,
                         const QualityTarget& target);

struct SharedPlan {
    QualityPlan plan;
    bool read = false;  // from the file; else made here, and written there
};

// The plan in `file` if there is one, else planQuality()'s, written there
// for the renders that follow.
SharedPlan sharedPlan(const std::filesystem::path& file, const Scene& scene,
                      const QualityTarget& target, int maxSamples, std::optional<int> depth);

}  // namespace whitted
