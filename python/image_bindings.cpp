// Images in and out (OpenImageIO, as the programs write them), their
// comparison as the project measures error, and whitted-field's scenes.
#include <cstring>
#include <filesystem>
#include <string>

#include "bindings.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "sphere_field.h"

namespace whitted::python {

namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// An array of shape (height, width, 3) as an Image; ValueError for any other shape.
Image imageOf(const FloatArray& array, const char* name) {
    if (array.ndim() != 3 || array.shape(2) != 3 || array.shape(0) < 1 || array.shape(1) < 1) {
        std::string shape;
        for (py::ssize_t i = 0; i < array.ndim(); ++i)
            shape += (i ? ", " : "") + std::to_string(array.shape(i));
        throw py::value_error(std::string(name) +
                              " must be an array of shape (height, width, 3), not (" + shape + ")");
    }
    Image image(int(array.shape(1)), int(array.shape(0)));
    std::memcpy(image.rgb.data(), array.data(), image.rgb.size() * sizeof(float));
    return image;
}

}  // namespace

py::array_t<float> arrayOf(const Image& image) {
    py::array_t<float> array({image.height, image.width, 3});
    std::memcpy(array.mutable_data(), image.rgb.data(), image.rgb.size() * sizeof(float));
    return array;
}

void bindImages(py::module_& m) {
    m.def(
        "write_image",
        [](const FloatArray& array, const std::filesystem::path& path) {
            const Image image = imageOf(array, "the image");
            try {
                writeImage(image, path, {});
            } catch (const ImageIoError& e) {
                throw py::value_error(e.what());
            }
        },
        py::arg("image"), py::arg("path"),
        "Writes a linear RGB array of shape (height, width, 3) in the format of the\n"
        "file's extension: PNG and JPEG 8-bit with the sRGB curve (clamped to [0, 1]),\n"
        "EXR, HDR and TIFF as floats. Atomic: a failed write leaves no file. Raises\n"
        "ValueError naming the file.");
    m.def(
        "read_image",
        [](const std::filesystem::path& path) {
            try {
                return arrayOf(readImage(path));
            } catch (const ImageIoError& e) {
                throw py::value_error(e.what());
            }
        },
        py::arg("path"),
        "Reads any image OpenImageIO knows as a linear RGB float32 array of shape\n"
        "(height, width, 3); 8-bit files are decoded from sRGB. Raises ValueError.");

    py::class_<ErrorStats>(m, "Comparison",
                           "How far an image is from a reference, as the project measures it.")
        .def_readonly("psnr", &ErrorStats::psnrSrgb8,
                      "PSNR of the 8-bit sRGB pictures, dB (peak 255); inf when identical.")
        .def_readonly("largest_error", &ErrorStats::largest,
                      "The largest difference of a pixel, in 8-bit codes.")
        .def_readonly("rmse", &ErrorStats::rmseSrgb8, "RMSE of the 8-bit codes.")
        .def_readonly("psnr_linear", &ErrorStats::psnrLinear, "PSNR of the linear values (peak 1).")
        .def_readonly("rmse_linear", &ErrorStats::rmseLinear, "RMSE of the linear values.")
        .def("__repr__", [](const ErrorStats& e) {
            return "<whitted.Comparison psnr=" +
                   py::str(py::float_(e.psnrSrgb8)).cast<std::string>() +
                   " dB, largest_error=" + py::str(py::float_(e.largest)).cast<std::string>() +
                   " codes>";
        });
    m.def(
        "compare",
        [](const FloatArray& image, const FloatArray& reference) {
            return measureError(imageOf(image, "image"), imageOf(reference, "reference"));
        },
        py::arg("image"), py::arg("reference"),
        "The error of `image` against `reference` (arrays of shape (height, width, 3)):\n"
        "PSNR in dB and the largest error in 8-bit codes of the sRGB pictures a user\n"
        "sees. A smaller image is compared as a viewer enlarges it.");

    m.def(
        "field",
        [](int count, std::uint32_t seed) {
            if (count < 0) throw py::value_error("count must be >= 0");
            FieldOptions options;
            options.count = count;
            options.seed = seed;
            return sphereField(options);
        },
        py::arg("count"), py::arg("seed") = 1,
        "A field of `count` small matte, mirror and glass balls on the seed's checker\n"
        "floor, as whitted-field writes it: the same count and seed give the same scene.");
}

}  // namespace whitted::python
