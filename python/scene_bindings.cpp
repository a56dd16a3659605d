// Scenes in Python: the file format's objects with its key names as
// attributes, load() and load_dict() with the file loader's validation and
// messages, save() and to_dict().
#include <cerrno>
#include <filesystem>
#include <string>

#include "bindings.h"
#include "scene/scene_io.h"

namespace whitted::python {

namespace {

// The scene file's text of a dict in its form; "format" and "version" may be
// left out.
std::string sceneText(const py::dict& d) {
    py::dict whole(d);
    const std::string format(scene_field::kFormat.key), version(scene_field::kVersion.key);
    if (!whole.contains(format)) whole[format.c_str()] = std::string(kSceneFormatName);
    if (!whole.contains(version)) whole[version.c_str()] = kSceneFormatVersion;
    return py::module_::import("json").attr("dumps")(whole).cast<std::string>();
}

Scene loadDict(const py::dict& d) {
    try {
        return parseScene(sceneText(d), "");
    } catch (const SceneError& e) {
        throw py::value_error(e.jsonPath().empty() ? e.reason() : e.jsonPath() + ": " + e.reason());
    }
}

Scene loadFile(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {
        errno = ENOENT;
        PyErr_SetFromErrnoWithFilename(PyExc_FileNotFoundError, path.c_str());
        throw py::error_already_set();
    }
    try {
        return loadScene(path);
    } catch (const SceneError& e) {
        throw py::value_error(e.what());
    }
}

py::dict toDict(const Scene& scene) {
    return fromJsonText(sceneToJson(scene));
}

std::string precisionOf(const RenderSettings& r) {
    return std::string(precisionName(r.precision));
}

void setPrecision(RenderSettings& r, const std::string& name) {
    const auto p = parsePrecision(name);
    if (!p)
        throw py::value_error("precision must be \"float\" or \"double\", not \"" + name + "\"");
    r.precision = *p;
}

void bindItems(py::module_& m) {
    py::class_<Checker>(m, "Checker",
                        "A material's checker pattern: every other cell of `size` takes `color`.")
        .def(py::init([](const glm::dvec3& color, double size) {
                 return Checker{color, size};
             }),
             py::arg("color") = glm::dvec3(0.0), py::arg("size") = 1.0)
        .def_readwrite("color", &Checker::color, "Linear RGB of the other cells, each in [0, 1].")
        .def_readwrite("size", &Checker::size, "Edge of a cell, in scene units, > 0.")
        .def(py::self == py::self);

    py::class_<Material>(m, "Material", "How a surface reflects, lets light through and bends it.")
        .def(py::init([](std::string name, const glm::dvec3& diffuse, double specular,
                         double shininess, double reflectivity, double transparency, double ior,
                         std::optional<Checker> checker) {
                 return Material{std::move(name), diffuse,      specular, shininess,
                                 reflectivity,    transparency, ior,      checker};
             }),
             py::arg("name"), py::arg("diffuse") = glm::dvec3(0.8), py::arg("specular") = 0.0,
             py::arg("shininess") = 50.0, py::arg("reflectivity") = 0.0,
             py::arg("transparency") = 0.0, py::arg("ior") = 1.5, py::arg("checker") = py::none())
        .def_readwrite("name", &Material::name, "Unique among the scene's materials.")
        .def_readwrite("diffuse", &Material::diffuse, "Linear RGB, each in [0, 1].")
        .def_readwrite("specular", &Material::specular, "Highlight strength ks, >= 0.")
        .def_readwrite("shininess", &Material::shininess, "Phong exponent n, >= 0.")
        .def_readwrite("reflectivity", &Material::reflectivity, "kr in [0, 1].")
        .def_readwrite("transparency", &Material::transparency,
                       "kt in [0, 1]; also what shadows let through.")
        .def_readwrite("ior", &Material::ior, "Index of refraction, > 0 (outside: 1).")
        // The material's own checker, not a copy: material.checker.size *= 2 changes it.
        .def_property(
            "checker",
            [](py::object self) -> py::object {
                auto& m = self.cast<Material&>();
                if (!m.checker) return py::none();
                return py::cast(&*m.checker, py::return_value_policy::reference_internal, self);
            },
            [](Material& m, std::optional<Checker> checker) { m.checker = std::move(checker); },
            "A Checker, or None.")
        .def(py::self == py::self);

    py::class_<Light>(m, "Light", "A point light; no fall-off with distance.")
        .def(py::init([](std::string name, const glm::dvec3& position, const glm::dvec3& color,
                         double intensity) {
                 return Light{std::move(name), position, color, intensity};
             }),
             py::arg("name"), py::arg("position") = glm::dvec3(0.0),
             py::arg("color") = glm::dvec3(1.0), py::arg("intensity") = 1.0)
        .def_readwrite("name", &Light::name, "Unique among the scene's lights.")
        .def_readwrite("position", &Light::position, "In scene units (y up).")
        .def_readwrite("color", &Light::color, "Linear RGB, each >= 0.")
        .def_readwrite("intensity", &Light::intensity, "Multiplies color, >= 0.")
        .def(py::self == py::self)
        .def("__repr__", [](const Light& l) { return "<whitted.Light \"" + l.name + "\">"; });

    py::class_<Sphere>(m, "Sphere", "A sphere and the name of its material.")
        .def(py::init([](std::string name, const glm::dvec3& center, double radius,
                         std::string material) {
                 return Sphere{std::move(name), center, radius, std::move(material)};
             }),
             py::arg("name"), py::arg("center") = glm::dvec3(0.0), py::arg("radius") = 1.0,
             py::arg("material") = "")
        .def_readwrite("name", &Sphere::name, "Unique among the scene's spheres.")
        .def_readwrite("center", &Sphere::center, "In scene units (y up).")
        .def_readwrite("radius", &Sphere::radius, "In scene units, > 0.")
        .def_readwrite("material", &Sphere::material, "The name of one of the scene's materials.")
        .def(py::self == py::self)
        .def("__repr__", [](const Sphere& s) {
            return "<whitted.Sphere \"" + s.name + "\" of \"" + s.material + "\">";
        });

    py::class_<Camera>(m, "Camera", "A pinhole camera.")
        .def(py::init([](const glm::dvec3& position, const glm::dvec3& lookAt, const glm::dvec3& up,
                         double vfov) {
                 return Camera{position, lookAt, up, vfov};
             }),
             py::arg("position") = glm::dvec3(0, 0, -1), py::arg("look_at") = glm::dvec3(0.0),
             py::arg("up") = glm::dvec3(0, 1, 0), py::arg("vfov_degrees") = 60.0)
        .def_readwrite("position", &Camera::position, "The eye, in scene units.")
        .def_readwrite("look_at", &Camera::lookAt, "The point in the middle of the picture.")
        .def_readwrite("up", &Camera::up, "Which way is up in the picture.")
        .def_readwrite("vfov_degrees", &Camera::vfovDegrees,
                       "Vertical field of view, in (0, 180) degrees.")
        .def(py::self == py::self);

    py::class_<RenderSettings>(m, "RenderSettings", "What a render of the scene makes.")
        .def(py::init<>())
        .def_readwrite("width", &RenderSettings::width, "Pixels, 1 to 16384.")
        .def_readwrite("height", &RenderSettings::height, "Pixels, 1 to 16384.")
        .def_readwrite("max_depth", &RenderSettings::maxDepth,
                       "Bounces of reflection and refraction, 0 to 64.")
        .def_readwrite("samples_per_pixel", &RenderSettings::samplesPerPixel,
                       "Camera rays a pixel, 1 to 65536.")
        .def_property("precision", &precisionOf, &setPrecision, "\"float\" or \"double\".")
        .def(py::self == py::self);
}

}  // namespace

py::object fromJsonText(const std::string& text) {
    return py::module_::import("json").attr("loads")(text);
}

void raiseIfInvalid(const Scene& scene) {
    if (const auto problem = validateScene(scene))
        throw py::value_error(problem->jsonPath + ": " + problem->reason);
}

void bindScene(py::module_& m) {
    bindItems(m);
    py::bind_vector<std::vector<Sphere>>(m, "SphereList");
    py::bind_vector<std::vector<Light>>(m, "LightList");
    py::bind_vector<std::vector<Material>>(m, "MaterialList");
    // scene.spheres = [whitted.Sphere(...), ...] as well as in place.
    py::implicitly_convertible<py::list, std::vector<Sphere>>();
    py::implicitly_convertible<py::list, std::vector<Light>>();
    py::implicitly_convertible<py::list, std::vector<Material>>();

    py::class_<Scene>(m, "Scene",
                      "A scene: camera, render settings, background, ambient light, and lists of\n"
                      "materials, lights and spheres that a script changes in place.")
        .def(py::init<>())
        .def_readwrite("camera", &Scene::camera)
        .def_readwrite("render", &Scene::render)
        .def_readwrite("background", &Scene::background, "Linear RGB of rays that hit nothing.")
        .def_readwrite("ambient", &Scene::ambient, "Linear RGB added to every lit surface.")
        .def_readwrite("materials", &Scene::materials)
        .def_readwrite("lights", &Scene::lights)
        .def_readwrite("spheres", &Scene::spheres)
        .def(
            "save",
            [](const Scene& scene, const std::filesystem::path& path) {
                raiseIfInvalid(scene);
                saveScene(scene, path);
            },
            py::arg("path"),
            "Writes the scene file (atomically: a failed write leaves the old file).\n"
            "Raises ValueError for an invalid scene, naming the field.")
        .def("to_dict", &toDict, "The scene in the scene file's form.")
        .def(
            "copy", [](const Scene& s) { return Scene(s); }, "A copy to change apart.")
        .def("__copy__", [](const Scene& s) { return Scene(s); })
        .def(
            "__deepcopy__", [](const Scene& s, py::dict) { return Scene(s); }, py::arg("memo"))
        .def(py::self == py::self)
        .def("__repr__", [](const Scene& s) {
            return "<whitted.Scene: " + std::to_string(s.spheres.size()) + " spheres, " +
                   std::to_string(s.lights.size()) + " lights, " +
                   std::to_string(s.materials.size()) + " materials, " +
                   std::to_string(s.render.width) + "x" + std::to_string(s.render.height) + ">";
        });

    m.def("load", &loadFile, py::arg("path"),
          "Reads a scene file. Raises FileNotFoundError, or ValueError naming the file and\n"
          "the field, as whitted-render does: \"a.json: spheres[2].radius: must be > 0\".");
    m.def("load_dict", &loadDict, py::arg("d"),
          "A scene from a dict in the scene file's form (\"format\" and \"version\" may be\n"
          "left out). Raises ValueError naming the field: \"spheres[0].radius: must be > 0\".");
}

}  // namespace whitted::python
