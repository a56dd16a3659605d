#include "plan_file.h"

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "base/atomic_file.h"
#include "scene/scene_io.h"

namespace whitted {

namespace {

// v2: the plan's fields under --stats' names, and the scene's digest.
constexpr const char* kPlanFormat = "whitted-quality-plan v2";
constexpr const char* kCustomTarget = "custom";

std::string pictureText(int width, int height, Precision precision) {
    return std::to_string(width) + "x" + std::to_string(height) + " in " +
           std::string(precisionName(precision));
}

// What the plan file says it was made for, against `scene`: empty when alike.
std::string madeForAnother(const nlohmann::json& j, const Scene& scene) {
    const std::optional<Precision> precision = parsePrecision(j.at("precision").get<std::string>());
    if (!precision) return "the plan names no precision whitted-render knows";
    const std::string made =
        pictureText(j.at("width").get<int>(), j.at("height").get<int>(), *precision);
    const std::string wanted =
        pictureText(scene.render.width, scene.render.height, scene.render.precision);
    if (made != wanted) return "the plan is for a picture of " + made + ", this one is " + wanted;
    if (j.at("scene").get<std::string>() != sceneContentDigest(scene))
        return "the plan is for another scene (its spheres, lights, materials or camera differ)";
    return {};
}

}  // namespace

nlohmann::ordered_json planJson(const QualityPlan& plan) {
    const QualityTarget& t = plan.target;
    nlohmann::ordered_json q;
    q["target"] = t.name.empty() ? kCustomTarget : t.name;
    q["target_psnr_db"] = t.psnrDb;
    q["target_max_error_codes"] =
        t.largestCodes ? nlohmann::ordered_json(*t.largestCodes) : nullptr;
    q["max_depth"] = plan.maxDepth;
    q["depth_chosen"] = !plan.depthGiven;
    q["depth_short"] = plan.depthShort;
    q["reference_depth"] = plan.referenceDepth;
    q["depth_mse_codes2"] = plan.depthMse;
    q["depth_max_error_codes"] = plan.depthLargest;
    q["depth_max_error_samples"] = plan.depthLargestSamples;
    q["depth_measured_at_picture_size"] = plan.depthAtPictureSize;
    q["precision_mse_codes2"] = plan.precisionMse;
    q["precision_samples"] = plan.precisionSamples;
    q["probe_width"] = plan.probeWidth;
    q["probe_height"] = plan.probeHeight;
    q["probe_rays"] = plan.probeRays;
    q["planning_cpu_seconds"] = plan.cpuSeconds;
    q["sampling_mse_limit_codes2"] = plan.sampling.allowedMse;
    q["sampling_max_error_limit_codes"] = plan.sampling.allowedLargest;
    q["max_samples_per_pixel"] = plan.sampling.maxSamples;
    q["centres_first"] = plan.sampling.centresFirst;
    q["why"] = plan.why;
    return q;
}

QualityPlan planFromJson(const nlohmann::json& j) {
    QualityPlan plan;
    const std::string name = j.at("target").get<std::string>();
    plan.target.name = name == kCustomTarget ? std::string() : name;
    plan.target.psnrDb = j.at("target_psnr_db").get<double>();
    if (!j.at("target_max_error_codes").is_null())
        plan.target.largestCodes = j.at("target_max_error_codes").get<double>();
    plan.maxDepth = j.at("max_depth").get<int>();
    plan.depthGiven = !j.at("depth_chosen").get<bool>();
    plan.depthShort = j.at("depth_short").get<bool>();
    plan.referenceDepth = j.at("reference_depth").get<int>();
    plan.depthMse = j.at("depth_mse_codes2").get<double>();
    plan.depthLargest = j.at("depth_max_error_codes").get<double>();
    plan.depthLargestSamples = j.at("depth_max_error_samples").get<int>();
    plan.depthAtPictureSize = j.at("depth_measured_at_picture_size").get<bool>();
    plan.precisionMse = j.at("precision_mse_codes2").get<double>();
    plan.precisionSamples = j.at("precision_samples").get<int>();
    plan.probeWidth = j.at("probe_width").get<int>();
    plan.probeHeight = j.at("probe_height").get<int>();
    plan.probeRays = j.at("probe_rays").get<std::uint64_t>();
    plan.cpuSeconds = j.at("planning_cpu_seconds").get<double>();
    plan.sampling.allowedMse = j.at("sampling_mse_limit_codes2").get<double>();
    plan.sampling.allowedLargest = j.at("sampling_max_error_limit_codes").get<double>();
    plan.sampling.maxSamples = j.at("max_samples_per_pixel").get<int>();
    plan.sampling.centresFirst = j.at("centres_first").get<bool>();
    plan.why = j.at("why").get<std::string>();
    return plan;
}

void writePlanFile(const std::filesystem::path& file, const QualityPlan& plan, const Scene& scene) {
    nlohmann::ordered_json j;
    j["format"] = kPlanFormat;
    j["width"] = scene.render.width;
    j["height"] = scene.render.height;
    j["precision"] = std::string(precisionName(scene.render.precision));
    j["scene"] = sceneContentDigest(scene);
    j.update(planJson(plan));
    replaceFileWithText(file, j.dump(2) + "\n");
}

QualityPlan readPlanFile(const std::filesystem::path& file, const Scene& scene,
                         const QualityTarget& target) {
    const std::string name = file.string();
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(name + ": cannot read the plan");
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    QualityPlan plan;
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        if (j.at("format") != kPlanFormat)
            throw std::runtime_error("not a plan this whitted-render writes (format " +
                                     j.at("format").dump() + ")");
        if (const std::string another = madeForAnother(j, scene); !another.empty())
            throw std::runtime_error(another);
        plan = planFromJson(j);
        if (!(plan.target == target))
            throw std::runtime_error("the plan is for " + describeTarget(plan.target) + ", not " +
                                     describeTarget(target));
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(name + ": not a plan whitted-render wrote (" + e.what() + ")");
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(name + ": " + e.what());
    }
    if (plan.maxDepth < 0 || plan.maxDepth > kMaxDepth || plan.sampling.maxSamples < 1)
        throw std::runtime_error(name + ": not a plan whitted-render wrote (depth " +
                                 std::to_string(plan.maxDepth) + ", at most " +
                                 std::to_string(plan.sampling.maxSamples) + " samples)");
    return plan;
}

SharedPlan sharedPlan(const std::filesystem::path& file, const Scene& scene,
                      const QualityTarget& target, int maxSamples, std::optional<int> depth) {
    if (std::filesystem::exists(file)) return {readPlanFile(file, scene, target), true};
    SharedPlan made{planQuality(scene, target, maxSamples, depth), false};
    writePlanFile(file, made.plan, scene);
    return made;
}

}  // namespace whitted
