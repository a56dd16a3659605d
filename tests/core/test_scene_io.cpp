// Tests for core/scene_io.*: the SPEC §6 example and defaults, every kind of bad
// input refused with the file name and the exact JSON path, byte-stable save of
// every scene in scenes/, and atomic saving.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_io.h"
#include "support/core_support.h"
#include "support/test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::TempDir;

// The example of SPEC §6, verbatim.
const char* const kSpecExample = R"({
  "format": "whitted-scene", "version": 1,
  "camera":  {"position": [0,0.35,-1], "look_at": [0,0.25,0], "up": [0,1,0], "vfov_degrees": 73.74},
  "render":  {"width": 640, "height": 480, "max_depth": 2, "samples_per_pixel": 1, "precision": "float"},
  "background": [0.002, 0.002, 0.004],
  "ambient":    [0.05, 0.05, 0.05],
  "materials": [
    {"name": "blue",  "diffuse": [0,0,1], "specular": 1, "shininess": 50, "reflectivity": 0.5},
    {"name": "floor", "diffuse": [0.75,0.75,0.75], "specular": 1, "shininess": 50, "reflectivity": 0.25,
     "checker": {"color": [0,0,0], "size": 0.5}},
    {"name": "glass", "diffuse": [0,0,0], "specular": 1, "shininess": 200, "reflectivity": 0.1,
     "transparency": 0.9, "ior": 1.5}
  ],
  "lights":  [{"name": "key", "position": [5,5,-10], "color": [1,1,1], "intensity": 1}],
  "spheres": [
    {"name": "blue ball", "center": [1.0,0.2,2.0], "radius": 0.6, "material": "blue"},
    {"name": "floor", "center": [0,-99999.5,0], "radius": 99999, "material": "floor"}
  ]
})";

TEST(SceneIo, SpecExample_ParsesToItsValuesAndDefaults) {
    const Scene s = parseScene(kSpecExample, "example.json");
    EXPECT_EQ(s.camera.position, Vec3(0, 0.35, -1));
    EXPECT_EQ(s.camera.lookAt, Vec3(0, 0.25, 0));
    EXPECT_EQ(s.camera.up, Vec3(0, 1, 0));
    EXPECT_EQ(s.camera.vfovDegrees, 73.74);
    EXPECT_EQ(s.render.width, 640);
    EXPECT_EQ(s.render.height, 480);
    EXPECT_EQ(s.render.maxDepth, 2);
    EXPECT_EQ(s.render.samplesPerPixel, 1);
    EXPECT_EQ(s.render.precision, Precision::Float);
    EXPECT_EQ(s.background, Vec3(0.002, 0.002, 0.004));
    EXPECT_EQ(s.ambient, Vec3(0.05, 0.05, 0.05));

    ASSERT_EQ(s.materials.size(), 3u);
    const Material& blue = s.materials[0];
    EXPECT_EQ(blue.name, "blue");
    EXPECT_EQ(blue.diffuse, Vec3(0, 0, 1));
    EXPECT_EQ(blue.specular, 1);
    EXPECT_EQ(blue.shininess, 50);
    EXPECT_EQ(blue.reflectivity, 0.5);
    EXPECT_EQ(blue.transparency, 0) << "default transparency";
    EXPECT_EQ(blue.ior, 1.5) << "default ior";
    EXPECT_FALSE(blue.checker) << "default: no checker";
    const Material& floor = s.materials[1];
    ASSERT_TRUE(floor.checker);
    EXPECT_EQ(floor.checker->color, Vec3(0, 0, 0));
    EXPECT_EQ(floor.checker->size, 0.5);
    EXPECT_EQ(floor.reflectivity, 0.25);
    const Material& glass = s.materials[2];
    EXPECT_EQ(glass.shininess, 200);
    EXPECT_EQ(glass.transparency, 0.9);
    EXPECT_EQ(glass.ior, 1.5);
    EXPECT_EQ(glass.reflectivity, 0.1);

    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].name, "key");
    EXPECT_EQ(s.lights[0].position, Vec3(5, 5, -10));
    EXPECT_EQ(s.lights[0].color, Vec3(1, 1, 1));
    EXPECT_EQ(s.lights[0].intensity, 1);

    ASSERT_EQ(s.spheres.size(), 2u);
    EXPECT_EQ(s.spheres[0].name, "blue ball");
    EXPECT_EQ(s.spheres[0].center, Vec3(1, 0.2, 2));
    EXPECT_EQ(s.spheres[0].radius, 0.6);
    EXPECT_EQ(s.spheres[0].material, "blue");
    EXPECT_EQ(s.spheres[1].center, Vec3(0, -99999.5, 0));
    EXPECT_EQ(s.spheres[1].radius, 99999);
}

TEST(SceneIo, MinimalScene_GetsEveryDefaultOfSpec) {
    const Scene s = parseScene(R"({"format": "whitted-scene", "version": 1,
        "camera": {"position": [0, 0, -1], "look_at": [0, 0, 0]},
        "materials": [{"name": "m"}],
        "lights": [{"name": "l", "position": [1, 2, 3]}],
        "spheres": [{"name": "s", "center": [0, 0, 0], "radius": 1, "material": "m"}]})",
                               "minimal.json");
    EXPECT_EQ(s.camera.up, Vec3(0, 1, 0));
    EXPECT_EQ(s.camera.vfovDegrees, 60);
    EXPECT_EQ(s.render.width, 640);
    EXPECT_EQ(s.render.height, 480);
    EXPECT_EQ(s.render.maxDepth, 5);
    EXPECT_EQ(s.render.samplesPerPixel, 1);
    EXPECT_EQ(s.render.precision, Precision::Float);
    EXPECT_EQ(s.background, Vec3(0, 0, 0));
    EXPECT_EQ(s.ambient, Vec3(0.05, 0.05, 0.05));
    const Material& m = s.materials.at(0);
    EXPECT_EQ(m.diffuse, Vec3(0.8, 0.8, 0.8));
    EXPECT_EQ(m.specular, 0);
    EXPECT_EQ(m.shininess, 50);
    EXPECT_EQ(m.reflectivity, 0);
    EXPECT_EQ(m.transparency, 0);
    EXPECT_EQ(m.ior, 1.5);
    EXPECT_FALSE(m.checker);
    EXPECT_EQ(s.lights.at(0).color, Vec3(1, 1, 1));
    EXPECT_EQ(s.lights.at(0).intensity, 1);

    // Without any lists at all: an empty scene is still a scene.
    const Scene empty = parseScene(
        R"({"format": "whitted-scene", "version": 1,
            "camera": {"position": [0, 0, -1], "look_at": [0, 0, 0]}})",
        "empty.json");
    EXPECT_TRUE(empty.materials.empty());
    EXPECT_TRUE(empty.lights.empty());
    EXPECT_TRUE(empty.spheres.empty());
}

// ---- refusals -------------------------------------------------------------------

// The SPEC example with a third sphere and a second light, so that paths like
// spheres[2] and lights[1] exist.
json badInputBase() {
    json j = json::parse(kSpecExample);
    j["lights"].push_back({{"name", "fill"}, {"position", {-5, 3, -5}}, {"intensity", 0.3}});
    j["spheres"].push_back({{"name", "glass ball"},
                            {"center", {-0.5, 0.3, 1.5}},
                            {"radius", 0.5},
                            {"material", "glass"}});
    return j;
}

struct BadCase {
    const char* what;
    std::function<void(json&)> mutate;
    std::string path;  // the exact JSON path expected in the message
};

// JSON cannot hold infinities; these markers are replaced by 1e999 in the text.
const char* const kInf = "@INF@";
const char* const kNegInf = "@NEGINF@";

std::string textOf(const json& j) {
    std::string text = j.dump(2);
    for (auto [marker, number] : {std::pair{kInf, "1e999"}, std::pair{kNegInf, "-1e999"}}) {
        const std::string quoted = std::string("\"") + marker + "\"";
        for (size_t p; (p = text.find(quoted)) != std::string::npos;)
            text.replace(p, quoted.size(), number);
    }
    return text;
}

std::vector<BadCase> badCases() {
    return {
        // format and version
        {"unknown format", [](json& j) { j["format"] = "whitted-scenery"; }, "format"},
        {"format not a string", [](json& j) { j["format"] = 1; }, "format"},
        {"format missing", [](json& j) { j.erase("format"); }, "format"},
        {"newer version", [](json& j) { j["version"] = 2; }, "version"},
        {"version as a string", [](json& j) { j["version"] = "1"; }, "version"},
        {"version missing", [](json& j) { j.erase("version"); }, "version"},
        // unknown keys, top level and nested
        {"unknown top-level key", [](json& j) { j["lamps"] = json::array(); }, "lamps"},
        {"unknown camera key", [](json& j) { j["camera"]["fov"] = 60; }, "camera.fov"},
        {"unknown render key", [](json& j) { j["render"]["threads"] = 2; }, "render.threads"},
        {"unknown material key",
         [](json& j) {
             j["materials"][1]["colour"] = {1, 1, 1};
         },
         "materials[1].colour"},
        {"unknown checker key", [](json& j) { j["materials"][1]["checker"]["colour"] = 1; },
         "materials[1].checker.colour"},
        {"unknown light key", [](json& j) { j["lights"][0]["power"] = 3; }, "lights[0].power"},
        {"unknown sphere key", [](json& j) { j["spheres"][2]["mass"] = 3; }, "spheres[2].mass"},
        // wrong types
        {"camera not an object", [](json& j) { j["camera"] = "front"; }, "camera"},
        {"position of 2 numbers",
         [](json& j) {
             j["camera"]["position"] = {0, 0};
         },
         "camera.position"},
        {"position element a string", [](json& j) { j["camera"]["position"][1] = "x"; },
         "camera.position[1]"},
        {"vfov a string", [](json& j) { j["camera"]["vfov_degrees"] = "wide"; },
         "camera.vfov_degrees"},
        {"width a string", [](json& j) { j["render"]["width"] = "640"; }, "render.width"},
        {"width fractional", [](json& j) { j["render"]["width"] = 640.5; }, "render.width"},
        {"spp a boolean", [](json& j) { j["render"]["samples_per_pixel"] = true; },
         "render.samples_per_pixel"},
        {"precision unknown", [](json& j) { j["render"]["precision"] = "half"; },
         "render.precision"},
        {"precision a number", [](json& j) { j["render"]["precision"] = 32; }, "render.precision"},
        {"background a string", [](json& j) { j["background"] = "black"; }, "background"},
        {"materials an object", [](json& j) { j["materials"] = json::object(); }, "materials"},
        {"material a string", [](json& j) { j["materials"][0] = "blue"; }, "materials[0]"},
        {"material name a number", [](json& j) { j["materials"][0]["name"] = 5; },
         "materials[0].name"},
        {"ior a string", [](json& j) { j["materials"][2]["ior"] = "1.5"; }, "materials[2].ior"},
        {"checker an array",
         [](json& j) {
             j["materials"][1]["checker"] = {0, 0, 0};
         },
         "materials[1].checker"},
        {"intensity null", [](json& j) { j["lights"][0]["intensity"] = nullptr; },
         "lights[0].intensity"},
        {"radius a string", [](json& j) { j["spheres"][1]["radius"] = "1"; }, "spheres[1].radius"},
        {"sphere material a number", [](json& j) { j["spheres"][0]["material"] = 0; },
         "spheres[0].material"},
        {"centre of 4 numbers",
         [](json& j) {
             j["spheres"][2]["center"] = {1, 2, 3, 4};
         },
         "spheres[2].center"},
        // required keys missing
        {"camera missing", [](json& j) { j.erase("camera"); }, "camera"},
        {"camera position missing", [](json& j) { j["camera"].erase("position"); },
         "camera.position"},
        {"material name missing", [](json& j) { j["materials"][0].erase("name"); },
         "materials[0].name"},
        {"light position missing", [](json& j) { j["lights"][0].erase("position"); },
         "lights[0].position"},
        {"sphere radius missing", [](json& j) { j["spheres"][1].erase("radius"); },
         "spheres[1].radius"},
        {"sphere material missing", [](json& j) { j["spheres"][1].erase("material"); },
         "spheres[1].material"},
        {"checker size missing", [](json& j) { j["materials"][1]["checker"].erase("size"); },
         "materials[1].checker.size"},
        // radius <= 0
        {"radius 0", [](json& j) { j["spheres"][2]["radius"] = 0; }, "spheres[2].radius"},
        {"radius negative", [](json& j) { j["spheres"][0]["radius"] = -0.6; }, "spheres[0].radius"},
        // negative colours
        {"negative diffuse",
         [](json& j) {
             j["materials"][0]["diffuse"] = {-0.1, 0, 1};
         },
         "materials[0].diffuse"},
        {"negative checker colour",
         [](json& j) {
             j["materials"][1]["checker"]["color"] = {0, -1, 0};
         },
         "materials[1].checker.color"},
        {"negative light colour",
         [](json& j) {
             j["lights"][0]["color"] = {1, 1, -0.001};
         },
         "lights[0].color"},
        {"negative background",
         [](json& j) {
             j["background"] = {0, -0.5, 0};
         },
         "background"},
        {"negative ambient",
         [](json& j) {
             j["ambient"] = {-0.05, 0.05, 0.05};
         },
         "ambient"},
        // ior <= 0
        {"ior 0", [](json& j) { j["materials"][2]["ior"] = 0; }, "materials[2].ior"},
        {"ior negative", [](json& j) { j["materials"][1]["ior"] = -1.5; }, "materials[1].ior"},
        // transparency and reflectivity outside [0, 1]
        {"transparency above 1", [](json& j) { j["materials"][2]["transparency"] = 1.01; },
         "materials[2].transparency"},
        {"transparency negative", [](json& j) { j["materials"][0]["transparency"] = -0.1; },
         "materials[0].transparency"},
        {"reflectivity above 1", [](json& j) { j["materials"][0]["reflectivity"] = 1.5; },
         "materials[0].reflectivity"},
        {"reflectivity negative", [](json& j) { j["materials"][1]["reflectivity"] = -0.5; },
         "materials[1].reflectivity"},
        // missing material
        {"sphere names a missing material", [](json& j) { j["spheres"][1]["material"] = "nope"; },
         "spheres[1].material"},
        // duplicate names, reported at the second occurrence
        {"duplicate material", [](json& j) { j["materials"][2]["name"] = "blue"; },
         "materials[2].name"},
        {"duplicate light", [](json& j) { j["lights"][1]["name"] = "key"; }, "lights[1].name"},
        {"duplicate sphere", [](json& j) { j["spheres"][2]["name"] = "floor"; }, "spheres[2].name"},
        // camera
        {"zero-length up",
         [](json& j) {
             j["camera"]["up"] = {0, 0, 0};
         },
         "camera.up"},
        // forward is look_at - position = (0, -0.1, 1)
        {"up parallel to view",
         [](json& j) {
             j["camera"]["up"] = {0, -0.1, 1};
         },
         "camera.up"},
        {"up antiparallel to view",
         [](json& j) {
             j["camera"]["up"] = {0, 0.2, -2};
         },
         "camera.up"},
        {"vfov 0", [](json& j) { j["camera"]["vfov_degrees"] = 0; }, "camera.vfov_degrees"},
        {"vfov 180", [](json& j) { j["camera"]["vfov_degrees"] = 180; }, "camera.vfov_degrees"},
        {"vfov negative", [](json& j) { j["camera"]["vfov_degrees"] = -30; },
         "camera.vfov_degrees"},
        {"vfov 200", [](json& j) { j["camera"]["vfov_degrees"] = 200; }, "camera.vfov_degrees"},
        // render limits
        {"width 0", [](json& j) { j["render"]["width"] = 0; }, "render.width"},
        {"width 16385", [](json& j) { j["render"]["width"] = 16385; }, "render.width"},
        {"width negative", [](json& j) { j["render"]["width"] = -640; }, "render.width"},
        {"height 0", [](json& j) { j["render"]["height"] = 0; }, "render.height"},
        {"height 16385", [](json& j) { j["render"]["height"] = 16385; }, "render.height"},
        {"max_depth -1", [](json& j) { j["render"]["max_depth"] = -1; }, "render.max_depth"},
        {"max_depth 65", [](json& j) { j["render"]["max_depth"] = 65; }, "render.max_depth"},
        {"spp 0", [](json& j) { j["render"]["samples_per_pixel"] = 0; },
         "render.samples_per_pixel"},
        {"spp 65537", [](json& j) { j["render"]["samples_per_pixel"] = 65537; },
         "render.samples_per_pixel"},
        // beyond the SPEC list, in the same spirit
        {"checker size 0", [](json& j) { j["materials"][1]["checker"]["size"] = 0; },
         "materials[1].checker.size"},
        {"negative intensity", [](json& j) { j["lights"][1]["intensity"] = -1; },
         "lights[1].intensity"},
        {"look_at equals position",
         [](json& j) {
             j["camera"]["look_at"] = {0, 0.35, -1};
         },
         "camera.look_at"},
    };
}

// Infinite numbers: JSON has no literal for them, but 1e999 overflows to infinity.
// (NaN is not valid JSON at all; see InvalidJson_RefusedNamingFileAndPlace.)
std::vector<BadCase> nonFiniteCases() {
    return {
        {"radius 1e999", [](json& j) { j["spheres"][2]["radius"] = kInf; }, "spheres[2].radius"},
        {"position -1e999", [](json& j) { j["camera"]["position"][0] = kNegInf; },
         "camera.position[0]"},
        {"intensity 1e999", [](json& j) { j["lights"][0]["intensity"] = kInf; },
         "lights[0].intensity"},
        {"shininess 1e999", [](json& j) { j["materials"][0]["shininess"] = kInf; },
         "materials[0].shininess"},
        {"width 1e999", [](json& j) { j["render"]["width"] = kInf; }, "render.width"},
        {"background 1e999", [](json& j) { j["background"][2] = kInf; }, "background[2]"},
    };
}

void expectRefused(const BadCase& c) {
    SCOPED_TRACE(c.what);
    json j = badInputBase();
    c.mutate(j);
    const std::string text = textOf(j);
    try {
        parseScene(text, "dir/bad scene.json");
        ADD_FAILURE() << c.what << ": accepted, expected a refusal at " << c.path << "\n" << text;
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.file(), "dir/bad scene.json");
        EXPECT_EQ(e.jsonPath(), c.path) << "message: " << what;
        // "<file>: <json path>: <reason>" (scene_io.h)
        EXPECT_EQ(what.rfind("dir/bad scene.json: " + c.path + ": ", 0), 0u) << "message: " << what;
        EXPECT_FALSE(e.reason().empty());
    } catch (const std::exception& e) {
        ADD_FAILURE() << c.what << ": threw something other than SceneError: " << e.what();
    }
}

TEST(SceneIo, BaseOfBadInputTable_IsAccepted) {
    EXPECT_NO_THROW(parseScene(textOf(badInputBase()), "base.json"));
}

TEST(SceneIo, EveryBadInput_RefusedNamingFileAndJsonPath) {
    for (const BadCase& c : badCases()) expectRefused(c);
}

TEST(SceneIo, InfiniteNumber_RefusedNamingFileAndJsonPath) {
    for (const BadCase& c : nonFiniteCases()) expectRefused(c);
}

// Among 200,000 spheres (past the finder's first table sizes, with probes
// that pass other names), a repeat far from its first is named with both.
TEST(SceneIo, RepeatedNameAmongManySpheres_NamesBothPlaces) {
    Scene scene;
    scene.materials = {{"m", {1, 1, 1}, 1, 50, 0, 0, 1.5, {}}};
    for (int i = 0; i < 200000; ++i)
        scene.spheres.push_back({"ball " + std::to_string(i), {double(i), 0, 5}, 0.5, "m"});
    EXPECT_FALSE(validateScene(scene).has_value());
    scene.spheres[150000].name = "ball 7";
    scene.spheres[190000].name = "ball 8";
    const std::optional<SceneProblem> p = validateScene(scene);
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(p->jsonPath, "spheres[150000].name");
    EXPECT_EQ(p->reason, "duplicate name \"ball 7\" (also spheres[7])");
}

// The same cases for the Python module's tests (tests/python/test_scene.py):
// each file's text and the message loading it gives, written where
// WHITTED_BAD_SCENES says (ctest's fixture bad_scenes sets it).
TEST(SceneIo, EveryBadInput_WrittenForThePythonModulesTests) {
    json cases = json::array();
    std::vector<BadCase> all = badCases();
    for (BadCase& c : nonFiniteCases()) all.push_back(std::move(c));
    for (const BadCase& c : all) {
        json j = badInputBase();
        c.mutate(j);
        const std::string text = textOf(j);
        try {
            parseScene(text, "bad scene.json");
            ADD_FAILURE() << c.what << ": accepted";
        } catch (const SceneError& e) {
            cases.push_back({{"what", c.what},
                             {"text", text},
                             {"message", e.what()},
                             {"field", e.jsonPath() + ": " + e.reason()}});
        }
    }
    EXPECT_EQ(cases.size(), all.size());
    if (const char* file = std::getenv("WHITTED_BAD_SCENES")) {
        std::ofstream out(file);
        out << cases.dump(1) << "\n";
        ASSERT_TRUE(out.good()) << file;
    }
}

TEST(SceneIo, InvalidJson_RefusedNamingFileAndPlace) {
    const std::vector<std::pair<const char*, std::string>> cases = {
        {"trailing comma", R"({"format": "whitted-scene", "version": 1,})"},
        {"unterminated", R"({"format": "whitted-scene", "version": 1, "camera": {)"},
        {"empty file", ""},
        {"NaN literal", R"({"format": "whitted-scene", "version": 1, "ambient": [NaN, 0, 0]})"},
        {"not JSON at all", "format = whitted-scene\n"},
    };
    for (const auto& [what, text] : cases) {
        SCOPED_TRACE(what);
        try {
            parseScene(text, "broken.json");
            ADD_FAILURE() << "accepted";
        } catch (const SceneError& e) {
            const std::string msg = e.what();
            EXPECT_EQ(msg.rfind("broken.json: ", 0), 0u) << msg;
            EXPECT_NE(msg.find("JSON"), std::string::npos) << msg;
        }
    }
    // The root must be an object.
    EXPECT_THROW(parseScene("[1, 2, 3]", "array.json"), SceneError);
}

TEST(SceneIo, BoundaryValues_AreAccepted) {
    const std::vector<std::pair<const char*, std::function<void(json&)>>> cases = {
        {"width 1", [](json& j) { j["render"]["width"] = 1; }},
        {"width 16384", [](json& j) { j["render"]["width"] = 16384; }},
        {"height 16384", [](json& j) { j["render"]["height"] = 16384; }},
        {"max_depth 0", [](json& j) { j["render"]["max_depth"] = 0; }},
        {"max_depth 64", [](json& j) { j["render"]["max_depth"] = 64; }},
        {"spp 65536", [](json& j) { j["render"]["samples_per_pixel"] = 65536; }},
        {"precision double", [](json& j) { j["render"]["precision"] = "double"; }},
        {"transparency 1", [](json& j) { j["materials"][2]["transparency"] = 1; }},
        {"reflectivity 1", [](json& j) { j["materials"][0]["reflectivity"] = 1; }},
        {"reflectivity 0", [](json& j) { j["materials"][0]["reflectivity"] = 0; }},
        {"vfov 0.01", [](json& j) { j["camera"]["vfov_degrees"] = 0.01; }},
        {"vfov 179.99", [](json& j) { j["camera"]["vfov_degrees"] = 179.99; }},
        {"tiny ior", [](json& j) { j["materials"][2]["ior"] = 0.001; }},
        {"tiny radius", [](json& j) { j["spheres"][0]["radius"] = 1e-9; }},
        {"black everything",
         [](json& j) {
             j["background"] = {0, 0, 0};
         }},
        {"same name in different lists", [](json& j) { j["lights"][0]["name"] = "floor"; }},
        {"version as 1.0", [](json& j) { j["version"] = 1.0; }},
    };
    for (const auto& [what, mutate] : cases) {
        json j = badInputBase();
        mutate(j);
        EXPECT_NO_THROW(parseScene(textOf(j), "ok.json")) << what;
    }
}

TEST(SceneIo, LoadMissingOrBadFile_ThrowsSceneErrorNamingTheFile) {
    TempDir dir;
    const fs::path missing = dir / "no such scene.json";
    try {
        loadScene(missing);
        ADD_FAILURE() << "loaded a missing file";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
    }
    json j = badInputBase();
    j["spheres"][2]["radius"] = -1;
    const fs::path bad = dir / "bad.json";
    test::writeFile(bad, j.dump());
    try {
        loadScene(bad);
        ADD_FAILURE() << "loaded a bad file";
    } catch (const SceneError& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind(bad.string() + ": spheres[2].radius: ", 0), 0u) << msg;
    }
}

// ---- saving --------------------------------------------------------------------

// Recursive, so that scenes/extremes/ and any later subfolder are covered too.
std::vector<fs::path> repositoryScenes() {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(WHITTED_SCENES_DIR))
        if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

// Both texts in full plus the first differing line, so a failure reads like a diff.
std::string describeDifference(const std::string& expected, const std::string& actual) {
    std::istringstream a(expected), b(actual);
    std::string la, lb;
    int line = 1;
    for (;; ++line) {
        const bool ga = bool(std::getline(a, la)), gb = bool(std::getline(b, lb));
        if (!ga && !gb) break;
        if (!ga || !gb || la != lb) break;
    }
    return "first difference at line " + std::to_string(line) + "\n--- file\n" + la +
           "\n+++ saved\n" + lb + "\n===== whole file =====\n" + expected +
           "===== whole saved text =====\n" + actual;
}

TEST(SceneIo, EveryRepositoryScene_LoadThenSaveIsByteIdentical) {
    const auto files = repositoryScenes();
    ASSERT_FALSE(files.empty()) << "no scenes in " << WHITTED_SCENES_DIR;
    TempDir dir;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        const std::string original = test::readFile(file);
        const Scene scene = loadScene(file);
        const std::string text = sceneToJson(scene);
        EXPECT_EQ(text, original) << describeDifference(original, text);
        const fs::path copy = dir / file.filename().string();
        saveScene(scene, copy);
        const std::string saved = test::readFile(copy);
        EXPECT_EQ(saved, original) << describeDifference(original, saved);
        EXPECT_EQ(loadScene(copy), scene);
    }
}

TEST(SceneIo, SpecExample_SavesInCanonicalFormThatIsStable) {
    const Scene s = parseScene(kSpecExample, "example.json");
    const std::string once = sceneToJson(s);
    const Scene again = parseScene(once, "saved.json");
    EXPECT_EQ(again, s);
    EXPECT_EQ(sceneToJson(again), once);
    // Keys appear in SPEC order.
    const char* keys[] = {"\"format\"",    "\"version\"",    "\"camera\"",
                          "\"render\"",    "\"background\"", "\"ambient\"",
                          "\"materials\"", "\"lights\"",     "\"spheres\""};
    size_t previous = 0;
    for (const char* k : keys) {
        const size_t p = once.find(k);
        ASSERT_NE(p, std::string::npos) << k;
        EXPECT_GE(p, previous) << k << " out of order in\n" << once;
        previous = p;
    }
    // The camera's own keys too.
    EXPECT_LT(once.find("\"position\""), once.find("\"look_at\""));
    EXPECT_LT(once.find("\"look_at\""), once.find("\"up\""));
    EXPECT_LT(once.find("\"up\""), once.find("\"vfov_degrees\""));
}

// A plan file's record of its scene (app/plan_file.h): the render settings
// do not change it, the least move of a ball or the camera does.
TEST(SceneIo, ContentDigest_IgnoresRenderSettingsAndSeesTheLeastEdit) {
    const Scene s = parseScene(kSpecExample, "example.json");
    const std::string digest = sceneContentDigest(s);
    EXPECT_EQ(digest.size(), 16u);
    Scene other = s;
    other.render.width = 1920;
    other.render.samplesPerPixel = 256;
    other.render.precision = Precision::Double;
    EXPECT_EQ(sceneContentDigest(other), digest);
    other = s;
    other.spheres[0].center.x = std::nextafter(other.spheres[0].center.x, 2.0);
    EXPECT_NE(sceneContentDigest(other), digest);
    other = s;
    other.camera.vfovDegrees += 1.0;
    EXPECT_NE(sceneContentDigest(other), digest);
}

TEST(SceneIo, RandomNumbersAndOddNames_SurviveSaveAndLoadExactly) {
    const unsigned seed = std::random_device{}();
    std::printf("seed %u\n", seed);
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1), wide(-1e6, 1e6);
    Scene s = parseScene(kSpecExample, "example.json");
    s.render.precision = Precision::Double;
    s.camera.vfovDegrees = 1 + 178 * unit(rng);
    s.ambient = {unit(rng), unit(rng) * 1e-12, 1e-300};
    s.materials[0].name = "quote \" backslash \\ tab \t unicode \xc3\xa9\xe2\x82\xac";
    s.spheres[0].material = s.materials[0].name;
    for (Material& m : s.materials) {
        m.diffuse = {unit(rng), unit(rng), unit(rng)};
        m.reflectivity = unit(rng);
        m.transparency = unit(rng);
        m.ior = 1 + unit(rng);
        m.shininess = 1e3 * unit(rng);
    }
    for (Sphere& sp : s.spheres) {
        sp.center = {wide(rng), wide(rng), wide(rng)};
        sp.radius = 1e-3 + 1e5 * unit(rng);
    }
    s.lights[0].intensity = 12345678901234567.0;  // integral but beyond 2^53
    ASSERT_FALSE(validateScene(s)) << validateScene(s)->jsonPath;
    const std::string text = sceneToJson(s);
    const Scene back = parseScene(text, "random.json");
    EXPECT_EQ(back, s) << text;
    EXPECT_EQ(sceneToJson(back), text);
}

TEST(SceneIo, SaveOverExistingFile_ReplacesItAndLeavesNoTemporaries) {
    TempDir dir;
    const fs::path file = dir / "scene.json";
    test::writeFile(file, "old contents that are not a scene");
    const Scene s = parseScene(kSpecExample, "example.json");
    saveScene(s, file);
    EXPECT_EQ(test::readFile(file), sceneToJson(s));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"}) << test::joined(dir.entries());
    // Saving twice is fine too.
    Scene changed = s;
    changed.render.width = 320;
    saveScene(changed, file);
    EXPECT_EQ(loadScene(file), changed);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"}) << test::joined(dir.entries());
}

TEST(SceneIo, SaveIntoMissingDirectory_ThrowsAndCreatesNothing) {
    TempDir dir;
    const fs::path file = dir / "no such dir" / "scene.json";
    const Scene s = parseScene(kSpecExample, "example.json");
    EXPECT_THROW(saveScene(s, file), std::runtime_error);
    EXPECT_FALSE(fs::exists(dir / "no such dir"));
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

// A full disk: saving to a link to /dev/full says "No space left on device",
// names the file, and leaves the device node and the directory as they were.
TEST(SceneIo, SaveToFullDisk_ThrowsNoSpaceNamingTheFile) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
    TempDir dir;
    const fs::path link = dir / "scene.json";
    fs::create_symlink("/dev/full", link);
    try {
        saveScene(test::seedScene(), link);
        ADD_FAILURE() << "saved to a full disk";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), link.string() + ": No space left on device");
    }
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
    fs::remove(link);
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

// Bytes this process has read through read() and its kind so far (Linux).
long long bytesReadByThisProcess() {
    std::ifstream io("/proc/self/io");
    std::string field;
    long long value = -1;
    while (io >> field >> value)
        if (field == "rchar:") return value;
    return -1;
}

// A file over the size limit is refused before it is read, by name, size and limit.
TEST(SceneIo, FileOverSizeLimit_RefusedWithItsSizeAndTheLimit) {
    TempDir dir;
    const fs::path file = dir / "huge.json";
    test::writeFile(file, "{");
    const SceneFileLimit limit{std::uintmax_t(64) << 20, "a test's limit"};
    fs::resize_file(file, limit.bytes + 1);  // sparse: costs no disk
    try {
        loadScene(file, {}, limit);
        ADD_FAILURE() << "loaded";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  file.string() +
                      ": is 65 MB; scene files larger than 64 MB (a test's limit) are refused");
    }
    fs::resize_file(file, limit.bytes);  // at the limit: read, then refused as JSON
    try {
        loadScene(file, {}, limit);
        ADD_FAILURE() << "loaded";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()).find("refused"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("invalid JSON"), std::string::npos) << e.what();
    }
}

// The machine's own limit: a quarter of its memory, never below 64 MB; a
// mistaken file of several times the machine's memory is refused unread.
TEST(SceneIo, FileLargerThanTheMachineCanHold_RefusedWithoutReadingIt) {
    const SceneFileLimit limit = sceneFileLimit();
    const std::uintmax_t memory = std::uintmax_t(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
    EXPECT_GE(limit.bytes, kMinSceneFileLimit);
    if (memory / 4 >= kMinSceneFileLimit) {
        EXPECT_EQ(limit.bytes, memory / 4);
        EXPECT_EQ(limit.why, "a quarter of this machine's memory");
    }
    TempDir dir;
    const fs::path file = dir / "mistake.json";
    test::writeFile(file, "{\"format\": \"whitted-scene\"");
    fs::resize_file(file, 4 * memory);  // sparse: costs no disk
    const long long readBefore = bytesReadByThisProcess();
    try {
        loadScene(file);
        ADD_FAILURE() << "loaded";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(file.string() + ": is ", 0), 0u) << what;
        EXPECT_NE(what.find("(a quarter of this machine's memory) are refused"), std::string::npos)
            << what;
    }
    if (readBefore >= 0) {
        EXPECT_LT(bytesReadByThisProcess() - readBefore, 1 << 20);
    }
}

}  // namespace
}  // namespace whitted
