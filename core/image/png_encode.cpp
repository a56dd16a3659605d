#include "image/png_encode.h"

#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <stdexcept>

#include "image/zlib_stripes.h"

namespace whitted {
namespace {

// libpng reports through these callbacks and leaves by longjmp, so nothing
// thrown may cross them: a failure is kept as text and libpng is told.
void appendToEncoded(png_structp png, png_bytep data, png_size_t length) {
    auto* encoded = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
    bool grown = true;
    try {
        encoded->insert(encoded->end(), data, data + length);
    } catch (...) {
        grown = false;
    }
    if (!grown) png_error(png, "out of memory");
}

void flushNothing(png_structp) {}

// The warnings too: libpng says what was wrong in a warning ("Image width is
// zero in IHDR") before its error ("Invalid IHDR data").
void keepMessage(png_structp png, png_const_charp message) {
    auto* reason = static_cast<std::string*>(png_get_error_ptr(png));
    try {
        *reason += (reason->empty() ? "" : "; ") + std::string(message);
    } catch (...) {
    }
}

[[noreturn]] void keepReasonAndLeave(png_structp png, png_const_charp message) {
    keepMessage(png, message);
    png_longjmp(png, 1);
}

// What libpng is given beside the picture, made before it starts: after its
// setjmp nothing here is created, changed or destroyed.
struct PngInput {
    std::vector<unsigned char> pixels;  // the image data of the IDAT chunk: a zlib stream
    std::vector<std::string> keys;
    std::vector<png_text> texts;
};

// Each row filtered by its left neighbour (PNG's Sub filter: a filter-type
// byte, then each byte less the byte of the pixel before), and zlib's level 5:
// the seed, glass and field renders at 1280x720 come out 1 to 6 % larger than
// OpenImageIO's files (level 6, libpng's choice of filter row by row), and the
// seed's whole process took 44 ms instead of 65, of which the encoding was half.
constexpr int kPngLevel = 5;
constexpr unsigned char kSubFilter = 1;

std::vector<unsigned char> compressedRows(const CodecPicture& picture, const unsigned char* codes) {
    const std::size_t stride = std::size_t(3) * std::size_t(std::max(0, picture.width));
    const auto subFiltered = [&](std::size_t y, unsigned char* out) {
        const unsigned char* row = codes + y * stride;
        out[0] = kSubFilter;
        std::copy_n(row, std::min<std::size_t>(3, stride), out + 1);
        for (std::size_t i = 3; i < stride; ++i) out[1 + i] = row[i] - row[i - 3];
    };
    return zlibOfRows(std::size_t(std::max(0, picture.height)), stride + 1, subFiltered, kPngLevel);
}

PngInput pngInput(const CodecPicture& picture, const void* codes) {
    PngInput in;
    in.pixels = compressedRows(picture, static_cast<const unsigned char*>(codes));
    in.keys.reserve(picture.attributes.size());  // the texts point into it
    for (const auto& [name, value] : picture.attributes) {
        if (value.integer || value.real) continue;
        in.keys.push_back(name == "ImageDescription" ? "Description" : name);
        png_text t{};
        t.compression = PNG_TEXT_COMPRESSION_NONE;
        t.key = const_cast<char*>(in.keys.back().c_str());
        t.text = const_cast<char*>(value.text.c_str());
        t.text_length = value.text.size();
        in.texts.push_back(t);
    }
    return in;
}

// Returns false, with `reason` set, where libpng failed.
bool writePng(const CodecPicture& picture, const PngInput& in, std::vector<unsigned char>& encoded,
              std::string& reason) {
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &reason, keepReasonAndLeave, keepMessage);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &encoded, appendToEncoded, flushNothing);
    png_set_IHDR(png, info, picture.width, picture.height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
    png_set_oFFs(png, info, picture.x, picture.y, PNG_OFFSET_PIXEL);
    if (!in.texts.empty())
        png_set_text(png, info, in.texts.data(), static_cast<int>(in.texts.size()));
    // The chunks before the image through libpng; the image's, compressed on
    // every core (zlib_stripes.h), and the end as chunks of our own: libpng
    // compresses rows on one thread only.
    png_write_info(png, info);
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IDAT"), in.pixels.data(),
                    in.pixels.size());
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IEND"), nullptr, 0);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

std::string encodePng(const CodecPicture& picture, const void* codes,
                      std::vector<unsigned char>& encoded) {
    if (!picture.eightBit || picture.channels != 3) return "a PNG is written from 8-bit RGB codes";
    PngInput in;
    try {
        in = pngInput(picture, codes);
    } catch (const std::runtime_error& e) {  // zlib's reason
        return e.what();
    }
    std::string reason;
    if (writePng(picture, in, encoded, reason)) return {};
    return reason.empty() ? "libpng could not start" : reason;
}

}  // namespace whitted
