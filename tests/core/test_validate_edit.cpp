// validateEdit() checks only what an edit changed; it must still report
// exactly what validateScene() reports for the edited scene, first problem
// and message included, or the editor would accept a scene its own file
// loader refuses (or word a refusal differently). Random edits of a valid
// scene, one to three changes at a time, compared with the full check.
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/core_support.h"

namespace whitted {
namespace {

Scene sceneWithBalls(int count) {
    Scene s = test::seedScene();
    for (int i = 0; i < count; ++i)
        s.spheres.push_back({"ball " + std::to_string(i), {i * 0.5, 0.2, 3.0}, 0.2, "blue"});
    return s;
}

using Change = std::function<void(Scene&, std::mt19937&)>;

std::vector<Change> changes() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    auto sphere = [](Scene& s, std::mt19937& rng) -> Sphere& {
        return s.spheres[std::uniform_int_distribution<size_t>(0, s.spheres.size() - 1)(rng)];
    };
    const std::vector<double> radii = {0.3, 0.0, -1.0, nan, inf, 1e-300};
    return {
        [=](Scene& s, std::mt19937& r) { sphere(s, r).radius = radii[r() % radii.size()]; },
        [=](Scene& s, std::mt19937& r) { sphere(s, r).center.y = r() % 2 ? 1.5 : nan; },
        [=](Scene& s, std::mt19937& r) { sphere(s, r).center.x = r() % 2 ? -inf : 7.0; },
        [=](Scene& s, std::mt19937& r) { sphere(s, r).material = r() % 2 ? "white" : "gone"; },
        [=](Scene& s, std::mt19937& r) { sphere(s, r).name = r() % 2 ? "ball 3" : ""; },
        [=](Scene& s, std::mt19937& r) { sphere(s, r).name = "new name " + std::to_string(r()); },
        [](Scene& s, std::mt19937& r) { s.lights[0].intensity = r() % 2 ? -1.0 : 2.0; },
        [](Scene& s, std::mt19937& r) { s.lights[0].color.z = r() % 2 ? -0.5 : 0.5; },
        [](Scene& s, std::mt19937& r) { s.materials[1].reflectivity = r() % 2 ? 2.0 : 0.3; },
        [](Scene& s, std::mt19937& r) { s.materials[0].ior = r() % 2 ? 0.0 : 1.2; },
        [](Scene& s, std::mt19937& r) { s.materials[2].name = r() % 2 ? "blue" : "ivory"; },
        [](Scene& s, std::mt19937& r) { s.camera.up = r() % 2 ? Vec3(0.0) : Vec3(0, 1, 0.1); },
        [](Scene& s, std::mt19937& r) { s.render.width = r() % 2 ? 0 : 320; },
        [](Scene& s, std::mt19937& r) { s.ambient.x = r() % 2 ? -1.0 : 0.2; },
        [](Scene& s, std::mt19937&) {
            s.spheres.push_back({"added", {0, 1, 4}, 0.5, "gone"});
        },
        [](Scene& s, std::mt19937&) { s.spheres.erase(s.spheres.begin()); },
    };
}

// The problem as the loader says it and as the editor reads it (typed).
std::string describe(const std::optional<SceneProblem>& p) {
    if (!p) return "valid";
    return p->jsonPath + ": " + p->reason + " [kind " + std::to_string(int(p->kind)) + ", field " +
           (p->field ? std::string(p->field->key) : "none") + ", list " +
           std::to_string(int(p->list)) + ", item " + std::to_string(p->index) + "]";
}

// `trials` edits of a scene of 300 balls, each one to three of `changes` at
// random: check(before, after) must say what validateScene(after) says, and
// each verdict must come up at least `least` times.
template <typename Check>
void expectTheWholeChecksVerdicts(const std::vector<Change>& changes, unsigned seed, int trials,
                                  int least, const Check& check) {
    std::mt19937 rng(seed);
    const Scene before = sceneWithBalls(300);
    ASSERT_FALSE(validateScene(before));
    int refused = 0, accepted = 0;
    for (int trial = 0; trial < trials; ++trial) {
        Scene after = before;
        const int count = 1 + static_cast<int>(rng() % 3);
        for (int k = 0; k < count; ++k) changes[rng() % changes.size()](after, rng);
        const std::string full = describe(validateScene(after));
        ASSERT_EQ(describe(check(before, after)), full) << "trial " << trial;
        (full == "valid" ? accepted : refused)++;
    }
    EXPECT_GT(accepted, least);
    EXPECT_GT(refused, least);
}

TEST(ValidateEdit, SameVerdictAndMessageAsTheWholeSceneCheck) {
    expectTheWholeChecksVerdicts(changes(), 12, 3000, 300, validateEdit);
}

// whitted-render changes only the settings of a scene its loader validated
// (flags, a quality plan's depth, a turntable's camera) and then checks them
// alone: validateSettingsEdit() must say what validateScene() says.
TEST(ValidateEdit, SettingsOnly_SameVerdictAndMessageAsTheWholeSceneCheck) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<Change> settings = {
        [](Scene& s, std::mt19937& r) { s.camera.up = r() % 2 ? Vec3(0.0) : Vec3(0, 1, 0.1); },
        [](Scene& s, std::mt19937& r) { s.camera.position = r() % 2 ? s.camera.lookAt : Vec3(4); },
        [=](Scene& s, std::mt19937& r) { s.camera.vfovDegrees = r() % 2 ? 180.0 : nan; },
        [](Scene& s, std::mt19937& r) { s.render.width = r() % 2 ? 0 : 320; },
        [](Scene& s, std::mt19937& r) { s.render.maxDepth = r() % 2 ? 65 : 3; },
        [](Scene& s, std::mt19937& r) { s.render.samplesPerPixel = r() % 2 ? 0 : 16; },
        [](Scene& s, std::mt19937& r) { s.ambient.x = r() % 2 ? -1.0 : 0.2; },
        [](Scene& s, std::mt19937& r) { s.background.y = r() % 2 ? 2.0 : 0.5; },
    };
    expectTheWholeChecksVerdicts(settings, 14, 1000, 100, [](const Scene&, const Scene& after) {
        return validateSettingsEdit(after);
    });
}

TEST(ValidateEdit, AnUnchangedSceneIsValid) {
    const Scene s = sceneWithBalls(10);
    EXPECT_FALSE(validateEdit(s, s));
}

// A program tells problems apart by their type, never by the reason's words:
// each kind of problem with its field (scene_fields.h) and item.
TEST(ValidateScene, ProblemsAreTyped_KindFieldAndItem) {
    struct Case {
        std::function<void(Scene&)> change;
        ProblemKind kind;
        const SceneField* field;
        SceneList list;
        std::size_t index;
        std::string jsonPath;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<Case> cases = {
        {[](Scene& s) { s.spheres[2].radius = 0; }, ProblemKind::BreaksRule, &scene_field::kRadius,
         SceneList::Spheres, 2, "spheres[2].radius"},
        {[=](Scene& s) { s.spheres[1].center.z = nan; }, ProblemKind::NotFinite,
         &scene_field::kCentre, SceneList::Spheres, 1, "spheres[1].center"},
        {[](Scene& s) { s.spheres[0].material = "gone"; }, ProblemKind::UnknownMaterial,
         &scene_field::kSphereMaterial, SceneList::Spheres, 0, "spheres[0].material"},
        {[](Scene& s) { s.spheres[3].name = s.spheres[1].name; }, ProblemKind::RepeatedName,
         &scene_field::kName, SceneList::Spheres, 3, "spheres[3].name"},
        {[](Scene& s) { s.lights[0].name.clear(); }, ProblemKind::EmptyName, &scene_field::kName,
         SceneList::Lights, 0, "lights[0].name"},
        {[](Scene& s) { s.lights[0].color.y = -1; }, ProblemKind::BreaksRule,
         &scene_field::kLightColour, SceneList::Lights, 0, "lights[0].color"},
        {[](Scene& s) {
             s.materials[1].checker = Checker{{1, 1, 1}, -2};
         },
         ProblemKind::BreaksRule, &scene_field::kCheckerSize, SceneList::Materials, 1,
         "materials[1].checker.size"},
        {[](Scene& s) { s.camera.lookAt = s.camera.position; }, ProblemKind::LookAtIsPosition,
         &scene_field::kLookAt, SceneList::None, 0, "camera.look_at"},
        {[](Scene& s) { s.camera.up = Vec3(0.0); }, ProblemKind::UpIsZero, &scene_field::kUp,
         SceneList::None, 0, "camera.up"},
        {[](Scene& s) { s.camera.up = s.camera.lookAt - s.camera.position; },
         ProblemKind::UpAlongView, &scene_field::kUp, SceneList::None, 0, "camera.up"},
        {[](Scene& s) { s.render.samplesPerPixel = 0; }, ProblemKind::BreaksRule,
         &scene_field::kSamples, SceneList::None, 0, "render.samples_per_pixel"},
        {[](Scene& s) { s.background.x = -0.1; }, ProblemKind::BreaksRule,
         &scene_field::kBackground, SceneList::None, 0, "background"},
    };
    for (const Case& c : cases) {
        Scene s = sceneWithBalls(4);
        c.change(s);
        const std::optional<SceneProblem> p = validateScene(s);
        ASSERT_TRUE(p) << c.jsonPath;
        EXPECT_EQ(p->jsonPath, c.jsonPath);
        EXPECT_EQ(p->kind, c.kind) << c.jsonPath;
        EXPECT_EQ(p->field, c.field) << c.jsonPath;
        EXPECT_EQ(p->list, c.list) << c.jsonPath;
        EXPECT_EQ(p->index, c.index) << c.jsonPath;
    }
}

}  // namespace
}  // namespace whitted
