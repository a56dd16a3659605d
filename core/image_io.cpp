#include "image_io.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <sstream>

#include <system_error>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "atomic_file.h"
#include "srgb.h"

namespace whitted {
namespace fs = std::filesystem;

const std::vector<ImageFormatInfo>& imageFormats() {
    static const std::vector<ImageFormatInfo> formats = {
        {ImageFormat::Png, "PNG", ".png", false},
        {ImageFormat::Jpeg, "JPEG", ".jpg .jpeg", false},
        {ImageFormat::Tiff, "TIFF (32-bit float)", ".tif .tiff", true},
        {ImageFormat::Exr, "OpenEXR", ".exr", true},
        {ImageFormat::Hdr, "Radiance HDR", ".hdr", true},
    };
    return formats;
}

std::optional<ImageFormatInfo> imageFormatFor(const fs::path& file) {
    std::string ext = file.extension().string();
    if (ext.empty()) return std::nullopt;
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const ImageFormatInfo& f : imageFormats()) {
        std::istringstream list{std::string(f.extensions)};
        for (std::string e; list >> e;)
            if (e == ext) return f;
    }
    return std::nullopt;
}

ImageMetadata makeImageMetadata(const RenderSettings& s, double renderSeconds,
                                std::string software) {
    ImageMetadata m;
    m.software = std::move(software);
    m.settings = s;
    m.renderSeconds = renderSeconds;
    std::ostringstream d;
    d << "Whitted ray tracer: " << s.width << "x" << s.height << ", " << s.samplesPerPixel
      << " samples per pixel, max depth " << s.maxDepth << ", " << precisionName(s.precision)
      << " precision, rendered in " << renderSeconds << " s";
    m.description = d.str();
    return m;
}

void writeImage(const Image& image, const fs::path& file, const ImageMetadata& metadata) {
    const auto format = imageFormatFor(file);
    if (!format)
        throw ImageIoError(file.string() +
                           ": unknown image extension (use .png, .jpg, .tif, .exr or .hdr)");
    if (image.width <= 0 || image.height <= 0) throw ImageIoError(file.string() + ": empty image");

    OIIO::ImageSpec spec(image.width, image.height, 3,
                         format->isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
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
    spec.attribute("oiio:ColorSpace", format->isFloat ? "Linear" : "sRGB");
    if (format->format == ImageFormat::Jpeg) spec.attribute("CompressionQuality", 95);

    std::vector<std::uint8_t> bytes;
    const void* pixels = image.rgb.data();
    if (!format->isFloat) {
        bytes.resize(image.rgb.size());
        std::transform(image.rgb.begin(), image.rgb.end(), bytes.begin(), srgbEncode8);
        pixels = bytes.data();
    }

    // Encoded in memory first, then written with checked system calls: the
    // format writers do not report a failed write (a full disk gave a
    // truncated PNG and no error), and a truncated file must never replace a
    // good one.
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

Image readImage(const fs::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw ImageIoError(file.string() + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels < 3) throw ImageIoError(file.string() + ": fewer than 3 channels");
    Image image(spec.width, spec.height);
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
            image.rgb[p * 3 + c] = eightBit ? srgbDecode8(codes[src]) : all[src];
        }
    return image;
}

std::string openImageIOVersion() {
    const int v = OIIO::openimageio_version();  // 20407 for 2.4.7
    return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." +
           std::to_string(v % 100);
}

}  // namespace whitted
