// libFuzzer entry point for the scene loader (issue 6): any bytes must end in a
// loaded scene or a SceneError with a message, never a crash, a hang or an
// unbounded allocation (the runner caps time and memory, see fuzz/README.md).
// A loaded scene must also survive the round trip the editor relies on: its
// canonical text loads back to an equal scene and the same bytes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "scene/scene_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
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
