// libFuzzer entry point for the scene loader: any bytes must end in a
// loaded scene or a SceneError with a message, never a crash, a hang or an
// unbounded allocation (the runner caps time and memory, see fuzz/README.md).
// A loaded scene must also survive the round trip the editor relies on: its
// canonical text loads back to an equal scene and the same bytes. The same
// bytes pasted from the clipboard (scene_fragment.h) must be refused naming
// the clipboard, or leave the scene pasted into valid. Whatever the fast reader
// reads, the full reader reads the same (scene_fast_read.h).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "scene/scene_fast_read.h"
#include "scene/scene_fragment.h"
#include "scene/scene_io.h"
#include "scene/scene_json.h"

namespace {

// A small valid scene to paste into: one ball of one material.
whitted::Scene pasteTarget() {
    whitted::Scene s;
    s.camera = whitted::Camera{{0, 1, -4}, {0, 0, 0}, {0, 1, 0}, 50};
    s.materials = {whitted::Material{"m", {0.8, 0.2, 0.2}, 0.5, 50, 0, 0, 1.5, std::nullopt}};
    s.spheres = {whitted::Sphere{"ball", {0, 0, 0}, 1, "m"}};
    return s;
}

void pasteChecked(const std::string& text) {
    static const whitted::Scene into = pasteTarget();
    try {
        const whitted::PasteResult pasted = whitted::pasteFragment(into, text);
        if (whitted::validateScene(pasted.scene)) std::abort();
    } catch (const whitted::SceneError& e) {
        if (std::string(e.what()).rfind("clipboard: ", 0) != 0) std::abort();
    }
}

// The fast reader reads only what the full reader reads, and reads it the same.
void fastReaderAgrees(const std::string& text) {
    std::string padded = text;
    padded.resize(text.size() + whitted::detail::fastReadPadding());
    const std::optional<whitted::Scene> fast =
        whitted::detail::readSceneFast(padded.data(), text.size(), padded.size());
    if (!fast) return;
    try {
        const whitted::Scene full = whitted::detail::parseSceneFully(text.data(), text.size(), "f");
        if (!(full == *fast)) std::abort();
    } catch (const whitted::SceneError&) {
        if (!whitted::validateScene(*fast)) std::abort();  // refused a scene the fast one read
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    pasteChecked(text);
    fastReaderAgrees(text);
    whitted::Scene scene;
    try {
        scene = whitted::parseScene(text, "fuzz.json");
    } catch (const whitted::SceneError& e) {
        if (std::string(e.what()).rfind("fuzz.json: ", 0) != 0) std::abort();  // names the file
        return 0;
    }
    const std::string canonical = whitted::sceneToJson(scene);
    const whitted::Scene again = whitted::parseScene(canonical, "canonical.json");
    if (!(again == scene) || whitted::sceneToJson(again) != canonical) std::abort();
    return 0;
}
