#include "image/image_io.h"

#include <dlfcn.h>

#include <cstdint>
#include <system_error>

#include "base/atomic_file.h"
#include "base/parallel_for.h"
#include "image/exr_codec.h"
#include "image/image_codec.h"
#include "image/png_encode.h"
#include "image/srgb.h"

namespace whitted {
namespace fs = std::filesystem;

namespace {

struct LoadedCodec {
    const ImageCodec* codec = nullptr;
    std::string failure;  // why it could not be loaded
};

// setImageCodecPath()'s path, if given.
fs::path& codecPathGiven() {
    static fs::path given;
    return given;
}

// The plug-in lies where the build and the install put it, relative to the
// program (CMake: WHITTED_CODEC_FROM_PROGRAM), so a build tree and an installed
// tree each find their own.
LoadedCodec loadCodec() {
    std::error_code error;
    const fs::path program = fs::read_symlink("/proc/self/exe", error);
    const fs::path plugin =
        !codecPathGiven().empty()
            ? codecPathGiven()
            : (program.parent_path() / WHITTED_CODEC_FROM_PROGRAM).lexically_normal();
    void* handle = dlopen(plugin.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) return {nullptr, "cannot load the image library: " + std::string(dlerror())};
    using Entry = const ImageCodec* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, "whitted_image_codec"));
    if (!entry) return {nullptr, "cannot load the image library: " + std::string(dlerror())};
    return {entry(), {}};
}

}  // namespace

void setImageCodecPath(const fs::path& plugin) {
    codecPathGiven() = plugin;
}

namespace {

const LoadedCodec& loadedCodec() {
    static const LoadedCodec loaded = loadCodec();
    return loaded;
}

const ImageCodec& codecFor(const fs::path& file) {
    const LoadedCodec& loaded = loadedCodec();
    if (!loaded.codec) throw ImageIoError(file.string() + ": " + loaded.failure);
    return *loaded.codec;
}

ImageFormatInfo formatOrThrow(const fs::path& file) {
    const auto format = imageFormatFor(file);
    if (!format)
        throw ImageIoError(file.string() +
                           ": unknown image extension (use .png, .jpg, .tif, .exr or .hdr)");
    return *format;
}

CodecAttribute text(std::string value) {
    return {std::move(value), std::nullopt, std::nullopt};
}
CodecAttribute integer(int value) {
    return {{}, value, std::nullopt};
}
CodecAttribute real(float value) {
    return {{}, std::nullopt, value};
}

// The picture as the format stores it: 8-bit sRGB codes (made here) or the
// image's linear floats (pixelsOf() points at them).
CodecPicture pictureOf(const Image& image, const fs::path& file, const ImageFormatInfo& format,
                       const ImageMetadata& metadata) {
    if (image.width <= 0 || image.height <= 0) throw ImageIoError(file.string() + ": empty image");
    CodecPicture p;
    p.width = p.fullWidth = image.width;
    p.height = p.fullHeight = image.height;
    p.eightBit = !format.isFloat;
    if (p.eightBit) {
        p.codes.resize(image.rgb.size());
        // On every core: a 1280x720 picture's codes took 3 ms on one, a twentieth
        // of writing the seed's PNG.
        forEachChunk(
            int(image.rgb.size()), resolveThreadCount(0),
            [&](int, int begin, int end) {
                srgbEncode8(image.rgb.data() + begin, std::size_t(end - begin),
                            p.codes.data() + begin);
            },
            1 << 18);
    }
    auto& a = p.attributes;
    // Empty strings are left out: Debian's OpenImageIO asserts on an empty
    // ImageDescription when writing JPEG (iptc.cpp, encode_iptc_iim_one_tag).
    if (!metadata.software.empty()) a["Software"] = text(metadata.software);
    if (!metadata.description.empty()) a["ImageDescription"] = text(metadata.description);
    a["whitted:width"] = integer(metadata.settings.width);
    a["whitted:height"] = integer(metadata.settings.height);
    a["whitted:samples_per_pixel"] = integer(metadata.settings.samplesPerPixel);
    a["whitted:max_depth"] = integer(metadata.settings.maxDepth);
    a["whitted:precision"] = text(std::string(precisionName(metadata.settings.precision)));
    a["whitted:render_seconds"] = real(float(metadata.renderSeconds));
    if (!metadata.qualityTarget.empty()) {
        a["whitted:quality"] = text(qualityLine(metadata));
        a["whitted:quality_target"] = text(metadata.qualityTarget);
        if (!metadata.qualityReached.empty())
            a["whitted:quality_reached"] = text(metadata.qualityReached);
    }
    a["oiio:ColorSpace"] = text(format.isFloat ? "Linear" : "sRGB");
    if (format.format == ImageFormat::Jpeg) a["CompressionQuality"] = integer(95);
    return p;
}

// PNG and OpenEXR, which renders write most, are encoded here without the
// plug-in (png_encode.h says why); the other formats by the plug-in.
std::string encode(const fs::path& file, ImageFormat format, const CodecPicture& picture,
                   const void* pixels, std::vector<unsigned char>& encoded) {
    switch (format) {
        case ImageFormat::Png:
            return encodePng(picture, pixels, encoded);
        case ImageFormat::Exr:
            return encodeExr(picture, static_cast<const float*>(pixels), encoded);
        default:
            return codecFor(file).encode(file.string(), picture, pixels, encoded);
    }
}

// Encoded in memory first, then written with checked system calls: the
// format writers do not report a failed write (a full disk gave a truncated
// PNG and no error), and a truncated file must never replace a good one.
void encodeAndReplace(const fs::path& file, ImageFormat format, const CodecPicture& picture,
                      const Image& image) {
    const void* pixels = picture.eightBit ? static_cast<const void*>(picture.codes.data())
                                          : static_cast<const void*>(image.rgb.data());
    std::vector<unsigned char> encoded;
    const std::string failure = encode(file, format, picture, pixels, encoded);
    if (!failure.empty()) throw ImageIoError(file.string() + ": " + failure);
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

std::string textOf(const CodecPicture& p, const std::string& name) {
    const auto it = p.attributes.find(name);
    return it == p.attributes.end() ? std::string() : it->second.text;
}
int integerOf(const CodecPicture& p, const std::string& name, int absent) {
    const auto it = p.attributes.find(name);
    return it == p.attributes.end() ? absent : it->second.integer.value_or(absent);
}
float realOf(const CodecPicture& p, const std::string& name, float absent) {
    const auto it = p.attributes.find(name);
    return it == p.attributes.end() ? absent : it->second.real.value_or(absent);
}

ImageMetadata metadataOf(const CodecPicture& p) {
    ImageMetadata m;
    m.software = textOf(p, "Software");
    m.description = textOf(p, "ImageDescription");
    RenderSettings& r = m.settings;
    r.width = integerOf(p, "whitted:width", r.width);
    r.height = integerOf(p, "whitted:height", r.height);
    r.samplesPerPixel = integerOf(p, "whitted:samples_per_pixel", r.samplesPerPixel);
    r.maxDepth = integerOf(p, "whitted:max_depth", r.maxDepth);
    r.precision = parsePrecision(textOf(p, "whitted:precision")).value_or(r.precision);
    m.renderSeconds = realOf(p, "whitted:render_seconds", 0.0f);
    m.qualityTarget = textOf(p, "whitted:quality_target");
    m.qualityReached = textOf(p, "whitted:quality_reached");
    return m;
}

}  // namespace

void writeImage(const Image& image, const fs::path& file, const ImageMetadata& metadata) {
    const ImageFormatInfo format = formatOrThrow(file);
    encodeAndReplace(file, format.format, pictureOf(image, file, format, metadata), image);
}

void writeImagePart(const ImagePart& part, const fs::path& file, const ImageMetadata& metadata) {
    const ImageFormatInfo format = formatOrThrow(file);
    if (format.format != ImageFormat::Exr)
        throw ImageIoError(file.string() +
                           ": a part of a picture is written as OpenEXR (.exr), which records "
                           "where it belongs");
    CodecPicture picture = pictureOf(part.image, file, format, metadata);
    picture.x = part.window.x;
    picture.y = part.window.y;
    picture.fullWidth = part.fullWidth;
    picture.fullHeight = part.fullHeight;
    encodeAndReplace(file, format.format, picture, part.image);
}

namespace {

// OpenEXR files of RGB, which the farm's merge reads, are decoded here
// without the plug-in; anything else by the plug-in.
CodecPicture decode(const fs::path& file) {
    const auto format = imageFormatFor(file);
    if (format && format->format == ImageFormat::Exr)
        if (auto picture = decodeExr(file.string())) return std::move(*picture);
    CodecPicture picture;
    const std::string failure = codecFor(file).decode(file.string(), picture);
    if (!failure.empty()) throw ImageIoError(file.string() + ": " + failure);
    return picture;
}

}  // namespace

ImagePart readImagePart(const fs::path& file) {
    const CodecPicture picture = decode(file);
    if (picture.channels < 3) throw ImageIoError(file.string() + ": fewer than 3 channels");
    ImagePart part;
    part.image = Image(picture.width, picture.height);
    part.window = {picture.x, picture.y, picture.width, picture.height};
    part.fullWidth = picture.fullWidth;
    part.fullHeight = picture.fullHeight;
    part.metadata = metadataOf(picture);
    for (size_t p = 0; p < size_t(picture.width) * picture.height; ++p)
        for (int c = 0; c < 3; ++c) {
            const size_t src = p * picture.channels + c;
            part.image.rgb[p * 3 + c] =
                picture.eightBit ? srgbDecode8(picture.codes[src]) : picture.values[src];
        }
    return part;
}

Image readImage(const fs::path& file) {
    return readImagePart(file).image;
}

std::string openImageIOVersion() {
    const LoadedCodec& loaded = loadedCodec();
    if (!loaded.codec) return "not loaded (" + loaded.failure + ")";
    const int v = loaded.codec->version();  // 20407 for 2.4.7
    return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." +
           std::to_string(v % 100);
}

}  // namespace whitted
