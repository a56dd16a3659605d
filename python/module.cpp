// The compiled part of `import whitted` (whitted/__init__.py re-exports it).
#include <dlfcn.h>

#include <filesystem>

#include "bindings.h"
#include "image/image_io.h"

namespace {

// The image plug-in lies relative to this module, where the build tree or the
// install put it (python/CMakeLists.txt); python3's own place, by which the
// programs find theirs, says nothing of where the module is.
void findImageCodec() {
    namespace fs = std::filesystem;
    Dl_info info;
    if (!dladdr(reinterpret_cast<void*>(&findImageCodec), &info) || !info.dli_fname) return;
    const fs::path here = fs::path(info.dli_fname).parent_path();
    for (const char* relative :
         {WHITTED_CODEC_FROM_BUILT_MODULE, WHITTED_CODEC_FROM_INSTALLED_MODULE}) {
        const fs::path plugin = (here / relative).lexically_normal();
        std::error_code error;
        if (fs::exists(plugin, error)) {
            whitted::setImageCodecPath(plugin);
            return;
        }
    }
}

}  // namespace

PYBIND11_MODULE(_whitted, m) {
    m.doc() = "The Whitted ray tracer: scenes, renders to NumPy arrays, images.";
    findImageCodec();
    whitted::python::bindScene(m);
    whitted::python::bindRender(m);
    whitted::python::bindImages(m);
}
