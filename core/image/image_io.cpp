#include "image/image_io.h"

#include <cstdint>

#include <system_error>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "base/atomic_file.h"
#include "image/srgb.h"

namespace whitted {
namespace fs = std::filesystem;

namespace {

ImageFormatInfo formatOrThrow(const fs::path& file) {
    const auto format = imageFormatFor(file);
    if (!format)
        throw ImageIoError(file.string() +
                           ": unknown image extension (use .png, .jpg, .tif, .exr or .hdr)");
    return *format;
}

OIIO::ImageSpec imageSpec(const Image& image, const fs::path& file, const ImageFormatInfo& format,
                          const ImageMetadata& metadata) {
    if (image.width <= 0 || image.height <= 0) throw ImageIoError(file.string() + ": empty image");
    OIIO::ImageSpec spec(image.width, image.height, 3,
                         format.isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    // Empty strings are left out: Debian's OpenImageIO asserts on an empty
    // ImageDescription when writing JPEG (iptc.cpp, encode_iptc_iim_one_tag).
    if (!metadata.software.empty()) spec.attribute("Software", metadata.software);
    if (!metadata.description.empty()) spec.attribute("ImageDescription", metadata.description);
    spec.attribute("whitted:width", metadata.settings.width);
    spec.attribute("whitted:height", metadata.settings.height);
    spec.attribute("whitted:samples_per_pixel", metadata.settings.samplesPerPixel);
    spec.attribute("whitted:max_depth", metadata.settings.maxDepth);
    spec.attribute("whitted:precision", std::string(precisionName(metadata.settings.precision)));
    spec.attribute("whitted:render_seconds", float(metadata.renderSeconds));
    if (!metadata.qualityTarget.empty()) {
        spec.attribute("whitted:quality", qualityLine(metadata));
        spec.attribute("whitted:quality_target", metadata.qualityTarget);
        if (!metadata.qualityReached.empty())
            spec.attribute("whitted:quality_reached", metadata.qualityReached);
    }
    spec.attribute("oiio:ColorSpace", format.isFloat ? "Linear" : "sRGB");
    if (format.format == ImageFormat::Jpeg) spec.attribute("CompressionQuality", 95);
    return spec;
}

// Encoded in memory first, then written with checked system calls: the
// format writers do not report a failed write (a full disk gave a truncated
// PNG and no error), and a truncated file must never replace a good one.
void encodeAndReplace(const fs::path& file, const OIIO::ImageSpec& spec, const void* pixels) {
    std::vector<unsigned char> encoded;
    {
        OIIO::Filesystem::IOVecOutput memory(encoded);
        auto out = OIIO::ImageOutput::create(file.string());
        if (!out) throw ImageIoError(file.string() + ": " + OIIO::geterror());
        if (!out->set_ioproxy(&memory) || !out->open(file.string(), spec))
            throw ImageIoError(file.string() + ": " + out->geterror());
        const bool wrote = out->write_image(spec.format, pixels);
        const bool closed = out->close();
        if (!wrote || !closed) throw ImageIoError(file.string() + ": " + out->geterror());
    }
    try {
        replaceFileAtomically(file, [&](const fs::path& temp) {
            writeAllBytes(temp, {reinterpret_cast<const char*>(encoded.data()), encoded.size()});
        });
    } catch (const std::system_error& e) {
        throw ImageIoError(file.string() + ": " + e.code().message());
    } catch (const std::exception& e) {
        throw ImageIoError(file.string() + ": " + e.what());
    }
}

}  // namespace

void writeImage(const Image& image, const fs::path& file, const ImageMetadata& metadata) {
    const ImageFormatInfo format = formatOrThrow(file);
    const OIIO::ImageSpec spec = imageSpec(image, file, format, metadata);
    std::vector<std::uint8_t> bytes;
    const void* pixels = image.rgb.data();
    if (!format.isFloat) {
        bytes.resize(image.rgb.size());
        srgbEncode8(image.rgb.data(), image.rgb.size(), bytes.data());
        pixels = bytes.data();
    }
    encodeAndReplace(file, spec, pixels);
}

void writeImagePart(const ImagePart& part, const fs::path& file, const ImageMetadata& metadata) {
    const ImageFormatInfo format = formatOrThrow(file);
    if (format.format != ImageFormat::Exr)
        throw ImageIoError(file.string() +
                           ": a part of a picture is written as OpenEXR (.exr), which records "
                           "where it belongs");
    OIIO::ImageSpec spec = imageSpec(part.image, file, format, metadata);
    spec.x = part.window.x;
    spec.y = part.window.y;
    spec.full_x = 0;
    spec.full_y = 0;
    spec.full_width = part.fullWidth;
    spec.full_height = part.fullHeight;
    encodeAndReplace(file, spec, part.image.rgb.data());
}

ImagePart readImagePart(const fs::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw ImageIoError(file.string() + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels < 3) throw ImageIoError(file.string() + ": fewer than 3 channels");
    ImagePart part;
    part.image = Image(spec.width, spec.height);
    part.window = {spec.x - spec.full_x, spec.y - spec.full_y, spec.width, spec.height};
    part.fullWidth = spec.full_width;
    part.fullHeight = spec.full_height;
    ImageMetadata& m = part.metadata;
    m.software = spec.get_string_attribute("Software");
    m.description = spec.get_string_attribute("ImageDescription");
    RenderSettings& r = m.settings;
    r.width = spec.get_int_attribute("whitted:width", r.width);
    r.height = spec.get_int_attribute("whitted:height", r.height);
    r.samplesPerPixel = spec.get_int_attribute("whitted:samples_per_pixel", r.samplesPerPixel);
    r.maxDepth = spec.get_int_attribute("whitted:max_depth", r.maxDepth);
    r.precision =
        parsePrecision(spec.get_string_attribute("whitted:precision")).value_or(r.precision);
    m.renderSeconds = spec.get_float_attribute("whitted:render_seconds", 0.0f);
    m.qualityTarget = spec.get_string_attribute("whitted:quality_target");
    m.qualityReached = spec.get_string_attribute("whitted:quality_reached");
    const bool eightBit = spec.format == OIIO::TypeDesc::UINT8;
    std::vector<float> all(size_t(spec.width) * spec.height * spec.nchannels);
    std::vector<std::uint8_t> codes(eightBit ? all.size() : 0);
    const bool ok =
        eightBit ? in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, codes.data())
                 : in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data());
    if (!ok) throw ImageIoError(file.string() + ": " + in->geterror());
    for (size_t p = 0; p < size_t(spec.width) * spec.height; ++p)
        for (int c = 0; c < 3; ++c) {
            const size_t src = p * spec.nchannels + c;
            part.image.rgb[p * 3 + c] = eightBit ? srgbDecode8(codes[src]) : all[src];
        }
    return part;
}

Image readImage(const fs::path& file) {
    return readImagePart(file).image;
}

std::string openImageIOVersion() {
    const int v = OIIO::openimageio_version();  // 20407 for 2.4.7
    return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." +
           std::to_string(v % 100);
}

}  // namespace whitted
