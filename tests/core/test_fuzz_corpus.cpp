// The fuzzing corpus (tests/fuzz/corpus) as a regression test of the scene
// loader in the main suite, built by GCC like the program: every file ends in a
// scene that round-trips byte for byte, or in a SceneError that names the file,
// a JSON path or the parse position, and a reason.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scene/scene_fragment.h"
#include "scene/scene_io.h"
#include "support/core_support.h"
#include "support/test_support.h"

namespace whitted {
namespace {

TEST(FuzzCorpus, EveryInput_LoadsAndRoundTripsOrIsRefusedWithAMessage) {
    int loaded = 0, refused = 0;
    for (const auto& entry : std::filesystem::directory_iterator(WHITTED_FUZZ_CORPUS_DIR)) {
        SCOPED_TRACE(entry.path().filename().string());
        const std::string text = test::readFile(entry.path());
        try {
            const Scene scene = parseScene(text, "input.json");
            const std::string canonical = sceneToJson(scene);
            const Scene again = parseScene(canonical, "canonical.json");
            EXPECT_EQ(again, scene);
            EXPECT_EQ(sceneToJson(again), canonical);
            ++loaded;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.file(), "input.json");
            EXPECT_FALSE(e.reason().empty());
            EXPECT_EQ(std::string(e.what()).rfind("input.json: ", 0), 0u) << e.what();
            ++refused;
        }
    }
    // Both outcomes are exercised: the repository's scenes load, the broken ones do not.
    EXPECT_GE(loaded, 5);
    EXPECT_GE(refused, 10);
}

// The same bytes from the clipboard (Ctrl+V): refused naming the clipboard,
// never half-pasted, or pasted into a valid scene that stays valid.
TEST(FuzzCorpus, EveryInput_PastedIsRefusedWithAMessageOrLeavesTheSceneValid) {
    Scene into = test::seedScene(64, 36);
    ASSERT_FALSE(validateScene(into));
    int pasted = 0, refused = 0;
    for (const auto& entry : std::filesystem::directory_iterator(WHITTED_FUZZ_CORPUS_DIR)) {
        SCOPED_TRACE(entry.path().filename().string());
        const std::string text = test::readFile(entry.path());
        try {
            const PasteResult result = pasteFragment(into, text);
            EXPECT_FALSE(validateScene(result.scene));
            EXPECT_EQ(result.scene.spheres.size(), into.spheres.size() + result.newSpheres.size());
            ++pasted;
        } catch (const SceneError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("clipboard: ", 0), 0u) << e.what();
            ++refused;
        }
    }
    // The repository's scenes and the fragment paste; the broken files do not.
    EXPECT_GE(pasted, 5);
    EXPECT_GE(refused, 10);
}

}  // namespace
}  // namespace whitted
