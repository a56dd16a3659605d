#include "plan_file.h"

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"

namespace whitted {

namespace {

constexpr const char* kPlanFormat = "whitted-quality-plan v1";

nlohmann::ordered_json targetJson(const QualityTarget& t) {
    nlohmann::ordered_json j;
    j["name"] = t.name;
    j["psnr_db"] = t.psnrDb;
    j["max_error_codes"] = t.largestCodes ? nlohmann::ordered_json(*t.largestCodes) : nullptr;
    return j;
}

QualityTarget targetFrom(const nlohmann::json& j) {
    QualityTarget t;
    t.name = j.at("name").get<std::string>();
    t.psnrDb = j.at("psnr_db").get<double>();
    if (!j.at("max_error_codes").is_null()) t.largestCodes = j.at("max_error_codes").get<double>();
    return t;
}

std::string pictureText(int width, int height, const std::string& precision) {
    return std::to_string(width) + "x" + std::to_string(height) + " in " + precision;
}

}  // namespace

void writePlanFile(const std::filesystem::path& file, const QualityPlan& plan,
                   const RenderSettings& planned) {
    nlohmann::ordered_json j;
    j["format"] = kPlanFormat;
    j["width"] = planned.width;
    j["height"] = planned.height;
    j["precision"] = std::string(precisionName(planned.precision));
    j["target"] = targetJson(plan.target);
    j["max_depth"] = plan.maxDepth;
    j["depth_given"] = plan.depthGiven;
    j["depth_short"] = plan.depthShort;
    j["reference_depth"] = plan.referenceDepth;
    j["depth_mse_codes2"] = plan.depthMse;
    j["depth_max_error_codes"] = plan.depthLargest;
    j["depth_max_error_samples"] = plan.depthLargestSamples;
    j["depth_measured_at_picture_size"] = plan.depthAtPictureSize;
    j["precision_mse_codes2"] = plan.precisionMse;
    j["precision_samples"] = plan.precisionSamples;
    j["probe_width"] = plan.probeWidth;
    j["probe_height"] = plan.probeHeight;
    j["probe_rays"] = plan.probeRays;
    j["cpu_seconds"] = plan.cpuSeconds;
    j["sampling"] = {{"mse_limit_codes2", plan.sampling.allowedMse},
                     {"max_error_limit_codes", plan.sampling.allowedLargest},
                     {"max_samples_per_pixel", plan.sampling.maxSamples},
                     {"centres_first", plan.sampling.centresFirst}};
    j["why"] = plan.why;
    const std::string text = j.dump(2) + "\n";
    replaceFileAtomically(file,
                          [&](const std::filesystem::path& temp) { writeAllBytes(temp, text); });
}

QualityPlan readPlanFile(const std::filesystem::path& file, const RenderSettings& settings,
                         const QualityTarget& target) {
    const std::string name = file.string();
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(name + ": cannot read the plan");
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    QualityPlan plan;
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        if (j.at("format") != kPlanFormat)
            throw std::runtime_error("not a plan whitted-render wrote (format " +
                                     j.at("format").dump() + ")");
        const std::string made = pictureText(j.at("width").get<int>(), j.at("height").get<int>(),
                                             j.at("precision").get<std::string>());
        const std::string wanted = pictureText(settings.width, settings.height,
                                               std::string(precisionName(settings.precision)));
        if (made != wanted)
            throw std::runtime_error("the plan is for a picture of " + made + ", this one is " +
                                     wanted);
        plan.target = targetFrom(j.at("target"));
        if (!(plan.target == target))
            throw std::runtime_error("the plan is for " + describeTarget(plan.target) + ", not " +
                                     describeTarget(target));
        plan.maxDepth = j.at("max_depth").get<int>();
        plan.depthGiven = j.at("depth_given").get<bool>();
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
        plan.cpuSeconds = j.at("cpu_seconds").get<double>();
        const nlohmann::json& s = j.at("sampling");
        plan.sampling.allowedMse = s.at("mse_limit_codes2").get<double>();
        plan.sampling.allowedLargest = s.at("max_error_limit_codes").get<double>();
        plan.sampling.maxSamples = s.at("max_samples_per_pixel").get<int>();
        plan.sampling.centresFirst = s.at("centres_first").get<bool>();
        plan.why = j.at("why").get<std::string>();
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

QualityPlan sharedPlan(const std::filesystem::path& file, const Scene& scene,
                       const QualityTarget& target, int maxSamples, std::optional<int> depth) {
    if (std::filesystem::exists(file)) return readPlanFile(file, scene.render, target);
    QualityPlan plan = planQuality(scene, target, maxSamples, depth);
    writePlanFile(file, plan, scene.render);
    return plan;
}

}  // namespace whitted
