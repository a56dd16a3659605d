// Tests for core/scene/scene_fragment.*: copying items of scenes/seed.json to
// text and pasting them back (renamed, materials reused or added, values bit
// for bit), refusals worded as the scene file's, and whole scene files pasted.
#include <bit>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_fragment.h"
#include "scene/scene_io.h"

#include "support/core_support.h"

namespace whitted {
namespace {

Scene fragSeedScene() {
    return loadScene(WHITTED_SCENES_DIR "/seed.json");
}

std::string fragSeedText() {
    std::ifstream in(WHITTED_SCENES_DIR "/seed.json");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

bool fragSameBits(const Vec3& a, const Vec3& b) {
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
           std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

// The SceneError that pasting `text` throws; fails the test if none is thrown.
SceneError fragRefusal(const Scene& into, const std::string& text) {
    try {
        pasteFragment(into, text);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "pasted without a refusal: " << text;
    return SceneError("", "", "");
}

// A fragment of the given materials and spheres (JSON arrays' insides).
std::string fragText(const std::string& materials, const std::string& spheres) {
    return R"({"format": "whitted-scene-fragment", "version": 1, "materials": [)" + materials +
           R"(], "spheres": [)" + spheres + R"(], "lights": []})";
}

const char* const kFragBlue =
    R"({"name": "blue", "diffuse": [0, 0, 1], "specular": 1, "shininess": 50, "reflectivity": 0.5})";

TEST(SceneFragment, PasteIntoSameScene_RenamesItemsAndReusesMaterials) {
    const Scene seed = fragSeedScene();
    const PasteResult r = pasteFragment(seed, fragmentToJson(seed, {0, 1}, {0}));

    ASSERT_EQ(r.scene.spheres.size(), 6u);
    ASSERT_EQ(r.newSpheres, (std::vector<std::size_t>{4, 5}));
    ASSERT_EQ(r.newLights, (std::vector<std::size_t>{1}));
    const Sphere& blue = r.scene.spheres[4];
    const Sphere& purple = r.scene.spheres[5];
    EXPECT_EQ(blue.name, "blue ball 2");
    EXPECT_EQ(purple.name, "purple ball 2");
    EXPECT_EQ(r.scene.lights[1].name, "key 2");
    EXPECT_EQ(r.renamed, 3u);

    EXPECT_EQ(r.scene.materials, seed.materials) << "both materials reused, none added";
    EXPECT_EQ(r.materialsReused, 2u);
    EXPECT_EQ(r.materialsAdded, 0u);
    EXPECT_EQ(blue.material, "blue");
    EXPECT_EQ(purple.material, "purple");

    EXPECT_TRUE(fragSameBits(blue.center, seed.spheres[0].center));    // [1, 0.2, 2]
    EXPECT_TRUE(fragSameBits(purple.center, seed.spheres[1].center));  // [-0.95, 0.31, 1.25]
    EXPECT_EQ(std::bit_cast<std::uint64_t>(blue.radius), std::bit_cast<std::uint64_t>(0.6));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(purple.radius), std::bit_cast<std::uint64_t>(0.6));
    EXPECT_TRUE(fragSameBits(r.scene.lights[1].position, Vec3(5, 5, -10)));

    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(r.scene.spheres[i], seed.spheres[i]);
    EXPECT_EQ(r.scene.camera, seed.camera);
    EXPECT_FALSE(validateScene(r.scene));
}

TEST(SceneFragment, FragmentToJson_WritesUsedMaterialsAndItemsAsTheSceneFileDoes) {
    const Scene seed = fragSeedScene();
    // Indices out of order and repeated: each item once, in the scene's order.
    const std::string text = fragmentToJson(seed, {2, 0, 2}, {});
    const nlohmann::json j = nlohmann::json::parse(text);
    EXPECT_EQ(j.at("format"), "whitted-scene-fragment");
    EXPECT_EQ(j.at("version"), 1);
    ASSERT_EQ(j.at("materials").size(), 2u);
    EXPECT_EQ(j["materials"][0]["name"], "blue");
    EXPECT_EQ(j["materials"][1]["name"], "white");
    ASSERT_EQ(j.at("spheres").size(), 2u);
    EXPECT_EQ(j["spheres"][0]["name"], "blue ball");
    EXPECT_EQ(j["spheres"][1]["name"], "white ball");
    EXPECT_TRUE(j.at("lights").empty());

    // The very lines the scene file holds for those items.
    const std::string file = sceneToJson(seed);
    for (const char* line :
         {R"({"name": "blue ball", "center": [1, 0.2, 2], "radius": 0.6, "material": "blue"})",
          R"({"name": "white", "diffuse": [1, 0.99, 0.99], "specular": 1, "shininess": 50, )"
          R"("reflectivity": 0.5, "transparency": 0, "ior": 1.5})"}) {
        EXPECT_NE(file.find(line), std::string::npos) << line;
        EXPECT_NE(text.find(line), std::string::npos) << line;
    }
}

TEST(SceneFragment, FragmentToJson_IndexPastTheList_Throws) {
    const Scene seed = fragSeedScene();
    EXPECT_THROW(fragmentToJson(seed, {4}, {}), std::out_of_range);
    EXPECT_THROW(fragmentToJson(seed, {}, {1}), std::out_of_range);
}

TEST(SceneFragment, PasteIntoSceneWithoutThem_AddsMaterialsAndKeepsNames) {
    const Scene seed = fragSeedScene();
    Scene into;
    into.materials.push_back(test::makeMaterial("red", {1, 0, 0}));
    into.spheres.push_back({"ball", {0, 0, 3}, 0.5, "red"});

    const PasteResult r = pasteFragment(into, fragmentToJson(seed, {0, 1}, {0}));
    ASSERT_EQ(r.scene.materials.size(), 3u);
    EXPECT_EQ(r.scene.materials[0], into.materials[0]);
    EXPECT_EQ(r.scene.materials[1], seed.materials[0]);  // blue
    EXPECT_EQ(r.scene.materials[2], seed.materials[1]);  // purple
    EXPECT_EQ(r.materialsAdded, 2u);
    EXPECT_EQ(r.materialsReused, 0u);
    EXPECT_EQ(r.renamed, 0u);
    ASSERT_EQ(r.scene.spheres.size(), 3u);
    EXPECT_EQ(r.scene.spheres[1], seed.spheres[0]);
    EXPECT_EQ(r.scene.spheres[2], seed.spheres[1]);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    EXPECT_EQ(r.scene.lights[0], seed.lights[0]);
    EXPECT_FALSE(validateScene(r.scene));
}

TEST(SceneFragment, SameMaterialNameOtherFields_AddsItRenamedAndSpheresUseIt) {
    const Scene seed = fragSeedScene();
    Scene into = seed;
    into.materials[0].diffuse = {0, 1, 0};  // "blue" is green here
    into.materials.push_back(test::makeMaterial("blue 2", {0.5, 0.5, 1}));
    into.spheres.push_back({"pale ball", {2, 0.2, 3}, 0.3, "blue 2"});

    const PasteResult r = pasteFragment(into, fragmentToJson(seed, {0}, {}));
    ASSERT_EQ(r.scene.materials.size(), 6u);
    Material expected = seed.materials[0];
    expected.name = "blue 3";
    EXPECT_EQ(r.scene.materials[5], expected);
    EXPECT_EQ(r.scene.materials[0], into.materials[0]) << "the scene's own blue untouched";
    EXPECT_EQ(r.materialsAdded, 1u);
    EXPECT_EQ(r.materialsReused, 0u);
    ASSERT_EQ(r.newSpheres, (std::vector<std::size_t>{5}));
    EXPECT_EQ(r.scene.spheres[5].name, "blue ball 2");
    EXPECT_EQ(r.scene.spheres[5].material, "blue 3");
    EXPECT_FALSE(validateScene(r.scene));
}

TEST(SceneFragment, PasteAgain_NumbersOnFromTheLastNumber) {
    const Scene seed = fragSeedScene();
    const std::string text = fragmentToJson(seed, {0}, {});
    const PasteResult once = pasteFragment(seed, text);
    const PasteResult twice = pasteFragment(once.scene, text);
    EXPECT_EQ(twice.scene.spheres.back().name, "blue ball 3");

    const std::string copyOfThird = fragmentToJson(twice.scene, {twice.newSpheres[0]}, {});
    const PasteResult thrice = pasteFragment(twice.scene, copyOfThird);
    EXPECT_EQ(thrice.scene.spheres.back().name, "blue ball 4") << "not \"blue ball 3 2\"";
    EXPECT_EQ(thrice.scene.materials, seed.materials);
    EXPECT_FALSE(validateScene(thrice.scene));
}

TEST(SceneFragment, NewNames_AvoidThePastedItemsNamesToo) {
    Scene into;
    into.materials.push_back(test::makeMaterial("blue", {0, 0, 1}, 1, 0.5));
    into.spheres.push_back({"ball", {0, 0, 3}, 0.5, "blue"});
    const std::string text = fragText(
        kFragBlue, R"({"name": "ball", "center": [1, 0, 3], "radius": 0.5, "material": "blue"},
                               {"name": "ball 2", "center": [2, 0, 3], "radius": 0.5, "material": "blue"})");

    const PasteResult r = pasteFragment(into, text);
    ASSERT_EQ(r.scene.spheres.size(), 3u);
    EXPECT_EQ(r.scene.spheres[1].name, "ball 3");
    EXPECT_EQ(r.scene.spheres[2].name, "ball 2") << "no clash: keeps its name";
    EXPECT_EQ(r.renamed, 1u);
    EXPECT_EQ(r.materialsReused, 1u);
    EXPECT_FALSE(validateScene(r.scene));
}

TEST(SceneFragment, RoundTripIntoEmptyScene_GivesTheSameItems) {
    const Scene seed = fragSeedScene();
    const std::string text = fragmentToJson(seed, {0, 1, 2, 3}, {0});
    const PasteResult r = pasteFragment(Scene{}, text);
    EXPECT_EQ(r.scene.materials, seed.materials);
    EXPECT_EQ(r.scene.spheres, seed.spheres);
    EXPECT_EQ(r.scene.lights, seed.lights);
    EXPECT_EQ(fragmentToJson(r.scene, r.newSpheres, r.newLights), text) << "byte-stable";

    const PasteResult nothing = pasteFragment(seed, fragmentToJson(seed, {}, {}));
    EXPECT_EQ(nothing.scene, seed);
    EXPECT_TRUE(nothing.newSpheres.empty());
}

TEST(SceneFragment, WholeSceneFileText_PastesItsItemsButNotItsCamera) {
    const Scene seed = fragSeedScene();
    const PasteResult r = pasteFragment(Scene{}, fragSeedText());
    EXPECT_EQ(r.scene.materials, seed.materials);
    EXPECT_EQ(r.scene.spheres, seed.spheres);
    EXPECT_EQ(r.scene.lights, seed.lights);
    EXPECT_EQ(r.scene.camera, Camera{});
    EXPECT_EQ(r.scene.render, RenderSettings{});
    EXPECT_EQ(r.scene.background, Scene{}.background);

    const PasteResult again = pasteFragment(seed, sceneToJson(seed));
    EXPECT_EQ(again.scene.spheres.size(), 8u);
    EXPECT_EQ(again.scene.spheres[7].name, "floor 2");
    EXPECT_EQ(again.materialsReused, 4u);
}

TEST(SceneFragment, NotJson_IsRefused) {
    const Scene seed = fragSeedScene();
    const SceneError e = fragRefusal(seed, "blue ball, purple ball");
    EXPECT_EQ(e.file(), "clipboard");
    EXPECT_EQ(std::string(e.what()).rfind("clipboard: invalid JSON: parse error at line 1", 0), 0u)
        << e.what();
}

TEST(SceneFragment, JsonOfAnotherKind_IsRefused) {
    const Scene seed = fragSeedScene();
    EXPECT_STREQ(fragRefusal(seed, R"({"spheres": []})").what(),
                 "clipboard: format: expected \"whitted-scene-fragment\" or \"whitted-scene\", "
                 "found no format");
    EXPECT_STREQ(fragRefusal(seed, R"({"format": "whitted-image", "version": 1})").what(),
                 "clipboard: format: expected \"whitted-scene-fragment\" or \"whitted-scene\", "
                 "found \"whitted-image\"");
    EXPECT_STREQ(fragRefusal(seed, "[1, 2]").what(),
                 "clipboard: expected an object, found an array");
    EXPECT_STREQ(fragRefusal(seed, "0.6").what(), "clipboard: expected an object, found a number");
}

TEST(SceneFragment, NewerVersionOrUnknownKey_IsRefused) {
    const Scene seed = fragSeedScene();
    EXPECT_STREQ(fragRefusal(seed, R"({"format": "whitted-scene-fragment", "version": 2})").what(),
                 "clipboard: version: 2 is newer than this program reads (1)");
    EXPECT_STREQ(
        fragRefusal(seed, R"({"format": "whitted-scene-fragment", "version": 1, "camera": {}})")
            .what(),
        "clipboard: camera: unknown key");
}

TEST(SceneFragment, NegativeRadius_IsRefusedAsTheSceneFileRefusesIt) {
    const Scene seed = fragSeedScene();
    const char* const sphere =
        R"({"name": "blue ball", "center": [1, 0.2, 2], "radius": -0.6, "material": "blue"})";
    const SceneError e = fragRefusal(seed, fragText(kFragBlue, sphere));
    EXPECT_EQ(e.jsonPath(), "spheres[0].radius");
    EXPECT_STREQ(e.what(), "clipboard: spheres[0].radius: must be > 0, found -0.6");

    // The same sphere in a scene file: the same words.
    Scene file = seed;
    file.spheres = {seed.spheres[0]};
    file.spheres[0].radius = -0.6;
    try {
        parseScene(sceneToJson(file), "clipboard");
        ADD_FAILURE() << "the file was not refused";
    } catch (const SceneError& fileError) {
        EXPECT_STREQ(e.what(), fileError.what());
    }
    EXPECT_EQ(seed, fragSeedScene()) << "nothing pasted";
}

TEST(SceneFragment, BadFieldInAnItem_IsRefusedWithItsPath) {
    const Scene seed = fragSeedScene();
    EXPECT_STREQ(fragRefusal(seed, fragText(kFragBlue, R"({"name": "b", "center": [0, 0, 0],
                                                  "radius": "big", "material": "blue"})"))
                     .what(),
                 "clipboard: spheres[0].radius: expected a number, found a string");
    EXPECT_STREQ(fragRefusal(seed, fragText(R"({"name": "blue", "reflectivity": 1.5})", "")).what(),
                 "clipboard: materials[0].reflectivity: must be in [0, 1], found 1.5");
    EXPECT_STREQ(fragRefusal(seed, fragText("", R"({"name": "b", "center": [0, 0, 1e999],
                                                    "radius": 1, "material": "blue"})"))
                     .what(),
                 "clipboard: spheres[0].center[2]: must be a finite number (number overflow "
                 "parsing '1e999')");
}

TEST(SceneFragment, SphereNamingAMaterialNotInTheFragment_IsRefused) {
    const Scene seed = fragSeedScene();
    // "blue" is in the scene pasted into, but a fragment must bring its own.
    const SceneError e = fragRefusal(
        seed,
        fragText("", R"({"name": "b", "center": [0, 0, 0], "radius": 1, "material": "blue"})"));
    EXPECT_STREQ(e.what(), "clipboard: spheres[0].material: no material named \"blue\"");
}

}  // namespace
}  // namespace whitted
