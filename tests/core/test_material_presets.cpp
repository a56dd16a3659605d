// The material presets: valid scene materials with unique
// names, and the finishes their names promise.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "scene/material_presets.h"
#include "support/core_support.h"

namespace whitted {
namespace {

using test::preset;

TEST(MaterialPresets, SixWithUniqueNames_InMenuOrder) {
    std::set<std::string_view> names;
    for (const MaterialPreset& p : materialPresets()) names.insert(p.name);
    EXPECT_EQ(names.size(), materialPresets().size());
    ASSERT_EQ(materialPresets().size(), 6u);
    const char* const expected[] = {"Matte", "Plastic", "Mirror", "Chrome", "Glass", "Water"};
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(materialPresets()[i].name, expected[i]);
}

TEST(MaterialPresets, EveryPreset_OnASphere_PassesValidateScene) {
    Scene scene = test::seedScene();
    for (const MaterialPreset& p : materialPresets()) {
        Scene s = scene;
        s.materials.push_back(presetMaterial(p, "preset"));
        s.spheres[0].material = "preset";
        const auto problem = validateScene(s);
        EXPECT_FALSE(problem) << p.name << ": " << problem->jsonPath << ": " << problem->reason;
        // Whitted's sum adds these three; more than 1 would make the ball glow.
        const double diffuseMax = std::max({p.diffuse.x, p.diffuse.y, p.diffuse.z});
        EXPECT_LE(diffuseMax + p.reflectivity + p.transparency, 1.0 + 1e-12) << p.name;
    }
}

TEST(MaterialPresets, GlassAndWater_AreClearWithTheirIndices) {
    const MaterialPreset& glass = preset("Glass");
    EXPECT_NEAR(glass.transparency, 0.9, 0.05);
    EXPECT_DOUBLE_EQ(glass.ior, 1.5);
    EXPECT_LE(std::max({glass.diffuse.x, glass.diffuse.y, glass.diffuse.z}), 0.05);
    const MaterialPreset& water = preset("Water");
    EXPECT_DOUBLE_EQ(water.ior, 1.33);
    EXPECT_GE(water.transparency, 0.85);
    EXPECT_EQ(preset("Matte").specular, 0.0);
    EXPECT_EQ(preset("Matte").reflectivity, 0.0);
    EXPECT_GE(preset("Mirror").reflectivity, 0.9);
    EXPECT_EQ(preset("Mirror").transparency, 0.0);
}

TEST(MaterialPresets, WithPreset_KeepsNameAndChecker_SetsTheFinish) {
    Material floor;
    floor.name = "floor";
    floor.checker = Checker{{0.0, 0.0, 0.0}, 0.5};
    const Material glass = withPreset(floor, preset("Glass"));
    EXPECT_EQ(glass.name, "floor");
    EXPECT_EQ(glass.checker, floor.checker);
    EXPECT_EQ(glass.transparency, preset("Glass").transparency);
    EXPECT_EQ(glass.diffuse, preset("Glass").diffuse);
    EXPECT_EQ(presetMaterial(preset("Water"), "pond").name, "pond");
    EXPECT_EQ(presetMaterial(preset("Water"), "pond").ior, 1.33);
}

}  // namespace
}  // namespace whitted
