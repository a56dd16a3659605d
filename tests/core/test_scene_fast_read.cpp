// Tests for core/scene/scene_fast_read.*: the fast reader reads every shipped
// scene and the ordinary ways of writing one exactly as the full reader does,
// and hands back whatever it cannot read the same way, so that every message
// is still the full reader's. loadScene() reads a pipe whole, and stops at
// the size limit.
#include <sys/stat.h>

#include <csignal>

#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "scene/scene_fast_read.h"
#include "scene/scene_io.h"
#include "scene/scene_json.h"
#include "support/core_support.h"
#include "support/test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::optional<Scene> fast(const std::string& text) {
    std::string padded = text;
    padded.resize(text.size() + detail::fastReadPadding(), '\0');
    return detail::readSceneFast(padded.data(), text.size(), padded.size());
}

// The full reader's scene, or its message.
struct Outcome {
    std::optional<Scene> scene;
    std::string message;
};

template <typename Read>
Outcome outcomeOf(Read&& read) {
    try {
        return {read(), ""};
    } catch (const SceneError& e) {
        return {std::nullopt, e.what()};
    }
}

const std::string& seedText() {
    static const std::string text = test::readFile(WHITTED_SCENES_DIR "/seed.json");
    return text;
}

// The seed's text with `from` replaced by `to` (which must be there).
std::string seedWith(const std::string& from, const std::string& to) {
    std::string text = seedText();
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(SceneFastRead, EveryShippedScene_ReadAsTheFullReaderReadsIt) {
    int scenes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(WHITTED_SCENES_DIR)) {
        if (entry.path().extension() != ".json") continue;
        const std::string text = test::readFile(entry.path());
        const std::optional<Scene> read = fast(text);
        ASSERT_TRUE(read.has_value()) << entry.path() << " was handed back";
        EXPECT_EQ(*read, detail::parseSceneFully(text.data(), text.size(), "full.json"))
            << entry.path();
        ++scenes;
    }
    EXPECT_GE(scenes, 10);
}

TEST(SceneFastRead, OrdinaryWaysOfWritingAScene_ReadTheSame) {
    const std::vector<std::string> texts = {
        seedWith("\"width\": 640", "\"width\": 640.0"),
        seedWith("\"width\": 640", "\"width\": 6.4e2"),
        seedWith("\"radius\": 0.6", "\"radius\": 6E-1"),
        seedWith("[0, 0.35, -1]", "[-0, 3.5e-1, -1.0]"),
        seedWith("\"blue ball\"", "\"bl\\u00fce \\\"ball\\\" \\\\ \\/\""),
        seedWith("\"blue ball\"", "\"blüe ball ☀\""),
        seedWith("{\"name\": \"key\", \"position\": [5, 5, -10], \"color\": [1, 1, 1], "
                 "\"intensity\": 1}",
                 "{ \"intensity\" : 1 "
                 ",\r\n\t\"color\":[1,1,1],\"position\":[5,5,-10],\"name\":\"key\"}"),
        seedText() + "\n\n \t\r\n",
        seedWith("\"ambient\": [0.05, 0.05, 0.05],\n", ""),
    };
    for (const std::string& text : texts) {
        const std::optional<Scene> read = fast(text);
        ASSERT_TRUE(read.has_value()) << text;
        EXPECT_EQ(*read, detail::parseSceneFully(text.data(), text.size(), "full.json")) << text;
    }
    EXPECT_EQ(fast(texts[5])->spheres[0].name, "blüe ball ☀");
    EXPECT_EQ(fast(texts[4])->spheres[0].name, "blüe \"ball\" \\ /");
}

TEST(SceneFastRead, WhatOnlyTheFullReaderJudges_HandedBackAndRefusedAsBefore) {
    const std::vector<std::string> texts = {
        seedWith("\"version\": 1", "\"version\": 1, \"colour\": 3"),   // unknown key
        seedWith("\"version\": 1", "\"version\": 1, \"version\": 1"),  // repeated key
        seedWith("\"radius\": 0.6", "\"radius\": \"0.6\""),            // a string for a number
        seedWith("\"radius\": 0.6", "\"radius\": 1e999"),              // not finite in double
        seedWith("\"radius\": 0.6, ", ""),                             // a missing field
        seedWith("\"version\": 1", "\"version\": 2"),                  // a newer format
        seedWith("\"width\": 640", "\"width\": 640.5"),                // not an integer
        seedWith("\"precision\": \"float\"", "\"precision\": \"half\""),
        seedWith("\"size\": 0.5", "\"size\": null"),
        seedWith("[0, 0.35, -1]", "[0, 0.35]"),
        seedWith("\"radius\": 0.6", "\"radius\": -0.6"),  // valid JSON, bad value
        seedText() + "x",                                 // text after the object
        seedText().substr(0, seedText().size() - 3),      // cut short
        seedWith("\"blue ball\"", "\"blue\tball\""),      // a raw control character
        seedWith("\"blue ball\"", "\"blue\\tball\""),     // an escaped one: read
        "\xef\xbb\xbf" + seedText(),                      // a byte order mark
        seedWith("\"blue ball\"", "\"blue \xff ball\""),  // not UTF-8
        "[]",
        "",
        // past 19 significant digits (simdjson 3.0.1 reads this 5.9e-35)
        seedWith("\"radius\": 0.6",
                 "\"radius\": 0.59999999999999997779553950749686919152736663818359375"),
    };
    for (const std::string& text : texts) {
        const Outcome full =
            outcomeOf([&] { return detail::parseSceneFully(text.data(), text.size(), "f.json"); });
        const Outcome both = outcomeOf([&] { return parseScene(text, "f.json"); });
        EXPECT_EQ(both.message, full.message) << text;
        EXPECT_EQ(both.scene, full.scene) << text;
        const std::optional<Scene> read = fast(text);
        if (!read) continue;
        if (full.scene) {
            EXPECT_EQ(*read, *full.scene) << text;
        } else {
            EXPECT_TRUE(validateScene(*read).has_value()) << text;
        }
    }
    EXPECT_FALSE(fast(texts[0]).has_value());
    EXPECT_FALSE(fast(texts[13]).has_value());
    EXPECT_FALSE(fast(texts[14]).has_value()) << "an escaped tab is left to the full reader";
    EXPECT_FALSE(fast(texts.back()).has_value());
    EXPECT_EQ(parseScene(texts.back(), "f.json").spheres[0].radius, 0.6);
}

// More spheres than one reading task takes (4,096; they are read in parts
// on every core): read in order, each where it belongs, and a problem in any
// part handed back to the full reader, whose message names its sphere.
TEST(SceneFastRead, SpheresReadInParts_AsTheFullReaderReadsThem) {
    Scene many = test::seedScene();
    for (int i = 0; i < 10000; ++i)
        many.spheres.push_back({"ball " + std::to_string(i), {i * 0.001, 0.5, 3}, 0.1, "blue"});
    const std::string text = sceneToJson(many);
    const std::optional<Scene> read = fast(text);
    ASSERT_TRUE(read.has_value());
    EXPECT_EQ(*read, many);

    // After the seed's four, "ball 4996" is spheres[5000], in the second
    // part; "ball 8188" the first of the third; "ball 9999" the last.
    const auto withSphere = [&](int ball, const std::string& from, const std::string& to) {
        const std::string name = "\"ball " + std::to_string(ball) + "\"";
        std::string changed = text;
        const std::size_t at = changed.find(from, changed.find(name));
        return changed.replace(at, from.size(), to);
    };
    const std::vector<std::pair<std::string, std::string>> refused = {
        {withSphere(4996, "\"radius\": 0.1", "\"radius\": \"0.1\""),
         "f.json: spheres[5000].radius: expected a number, found a string"},
        {withSphere(8188, "\"radius\": 0.1", "\"radius\": 0.1, \"colour\": 1"),
         "f.json: spheres[8192].colour: unknown key"},
        {withSphere(9999, "\"radius\": 0.1", "\"radius\": -0.1"),
         "f.json: spheres[10003].radius: must be > 0, found -0.1"},
    };
    for (const auto& [bad, message] : refused) {
        EXPECT_FALSE(fast(bad).has_value() && !validateScene(*fast(bad)));
        EXPECT_EQ(outcomeOf([&] { return parseScene(bad, "f.json"); }).message, message);
    }
}

// A pipe has no size beforehand: the text grows as it comes, and past the
// limit the loader stops reading and refuses it.
TEST(SceneLoad, FromAPipe_ReadWholeAndStoppedPastTheLimit) {
    // The loader closes the pipe at the limit; the writer must then fail, not die.
    const auto oldHandler = std::signal(SIGPIPE, SIG_IGN);
    TempDir dir;
    const fs::path pipe = dir / "scene.fifo";
    ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
    Scene big = test::seedScene();
    for (int i = 0; i < 30000; ++i)
        big.spheres.push_back({"ball " + std::to_string(i), {i * 0.01, 0, 3}, 0.1, "blue"});
    const std::string text = sceneToJson(big);
    ASSERT_GT(text.size(), std::size_t(2) << 20);
    const auto writer = [&] { test::writeFile(pipe, text); };
    std::thread first(writer);
    const Scene read = loadScene(pipe);
    first.join();
    EXPECT_EQ(read, big);

    std::thread second([&] {
        try {
            test::writeFile(pipe, text);
        } catch (...) {  // the reader may close its end first
        }
    });
    const SceneFileLimit limit{std::uintmax_t(1) << 20, "a test's limit"};
    try {
        loadScene(pipe, {}, limit);
        ADD_FAILURE() << "loaded past the limit";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), pipe.string() +
                                             ": is more than 1 MB; scene files larger than 1 MB "
                                             "(a test's limit) are refused");
    }
    second.join();
    std::signal(SIGPIPE, oldHandler);
}

}  // namespace
}  // namespace whitted
