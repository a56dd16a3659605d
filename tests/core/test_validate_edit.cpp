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

std::string describe(const std::optional<SceneProblem>& p) {
    return p ? p->jsonPath + ": " + p->reason : "valid";
}

TEST(ValidateEdit, SameVerdictAndMessageAsTheWholeSceneCheck) {
    std::mt19937 rng(12);
    const Scene before = sceneWithBalls(300);
    ASSERT_FALSE(validateScene(before));
    const std::vector<Change> all = changes();
    int refused = 0, accepted = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        Scene after = before;
        const int count = 1 + static_cast<int>(rng() % 3);
        for (int k = 0; k < count; ++k) all[rng() % all.size()](after, rng);
        const std::string full = describe(validateScene(after));
        ASSERT_EQ(describe(validateEdit(before, after)), full) << "trial " << trial;
        (full == "valid" ? accepted : refused)++;
    }
    // Both verdicts were exercised, many times.
    EXPECT_GT(accepted, 300);
    EXPECT_GT(refused, 300);
}

TEST(ValidateEdit, AnUnchangedSceneIsValid) {
    const Scene s = sceneWithBalls(10);
    EXPECT_FALSE(validateEdit(s, s));
}

}  // namespace
}  // namespace whitted
