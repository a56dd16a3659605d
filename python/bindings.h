// What every part of the Python module shares: the scene's lists bound as
// Python lists that edit the scene in place (scene.spheres[0].radius = 2
// changes the scene, not a copy), and points and colours as tuples of three
// floats.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <pybind11/stl_bind.h>

#include <vector>

#include "image/image.h"
#include "scene/scene.h"

PYBIND11_MAKE_OPAQUE(std::vector<whitted::Sphere>)
PYBIND11_MAKE_OPAQUE(std::vector<whitted::Light>)
PYBIND11_MAKE_OPAQUE(std::vector<whitted::Material>)

namespace pybind11::detail {

// glm::dvec3 <-> (x, y, z): from any sequence of three numbers, to a tuple.
template <>
struct type_caster<glm::dvec3> {
    PYBIND11_TYPE_CASTER(glm::dvec3, const_name("tuple[float, float, float]"));

    bool load(handle source, bool convert) {
        if (!isinstance<sequence>(source) || isinstance<str>(source)) return false;
        const auto items = reinterpret_borrow<sequence>(source);
        if (items.size() != 3) return false;
        for (int i = 0; i < 3; ++i) {
            make_caster<double> component;
            if (!component.load(items[i], convert)) return false;
            value[i] = cast_op<double>(component);
        }
        return true;
    }

    static handle cast(const glm::dvec3& v, return_value_policy, handle) {
        return make_tuple(v.x, v.y, v.z).release();
    }
};

}  // namespace pybind11::detail

namespace whitted::python {

namespace py = pybind11;

void bindScene(py::module_& m);
void bindRender(py::module_& m);
void bindImages(py::module_& m);

// The scene's validation, as a file's loading reports it, raised as
// ValueError: "spheres[0].radius: must be > 0".
void raiseIfInvalid(const Scene& scene);

// An image as a float32 array of shape (height, width, 3), copied.
py::array_t<float> arrayOf(const Image& image);

// JSON text (a scene file's, a render's stats) as Python dicts and lists.
py::object fromJsonText(const std::string& text);

}  // namespace whitted::python
