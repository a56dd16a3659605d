// The plug-in that calls OpenImageIO (image_codec.h says why it is one).
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "image/image_codec.h"

namespace whitted {
namespace {

OIIO::ImageSpec specOf(const CodecPicture& picture) {
    OIIO::ImageSpec spec(picture.width, picture.height, picture.channels,
                         picture.eightBit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.x = picture.x;
    spec.y = picture.y;
    spec.full_x = 0;
    spec.full_y = 0;
    spec.full_width = picture.fullWidth;
    spec.full_height = picture.fullHeight;
    for (const auto& [name, value] : picture.attributes) {
        if (value.integer)
            spec.attribute(name, *value.integer);
        else if (value.real)
            spec.attribute(name, *value.real);
        else
            spec.attribute(name, value.text);
    }
    return spec;
}

std::string encode(const std::string& fileName, const CodecPicture& picture, const void* pixels,
                   std::vector<unsigned char>& encoded) {
    const OIIO::ImageSpec spec = specOf(picture);
    OIIO::Filesystem::IOVecOutput memory(encoded);
    auto out = OIIO::ImageOutput::create(fileName);
    if (!out) return OIIO::geterror();
    if (!out->set_ioproxy(&memory) || !out->open(fileName, spec)) return out->geterror();
    const bool wrote = out->write_image(spec.format, pixels);
    const bool closed = out->close();
    if (!wrote || !closed) return out->geterror();
    return {};
}

// get_int() and get_float() answer their default for text that is no number:
// asked with two defaults, a value that is one answers the same twice.
CodecAttribute attributeOf(const OIIO::ParamValue& p) {
    CodecAttribute a{p.get_string(), std::nullopt, std::nullopt};
    if (const int i = p.get_int(0); i == p.get_int(1)) a.integer = i;
    if (const float f = p.get_float(0.0f); f == p.get_float(1.0f)) a.real = f;
    return a;
}

std::string decode(const std::string& fileName, CodecPicture& picture) {
    auto in = OIIO::ImageInput::open(fileName);
    if (!in) return OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    picture.width = spec.width;
    picture.height = spec.height;
    picture.channels = spec.nchannels;
    picture.x = spec.x - spec.full_x;
    picture.y = spec.y - spec.full_y;
    picture.fullWidth = spec.full_width;
    picture.fullHeight = spec.full_height;
    picture.eightBit = spec.format == OIIO::TypeDesc::UINT8;
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        picture.attributes[p.name().string()] = attributeOf(p);
    const size_t count = size_t(spec.width) * spec.height * spec.nchannels;
    bool ok = false;
    if (picture.eightBit) {
        picture.codes.resize(count);
        ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, picture.codes.data());
    } else {
        picture.values.resize(count);
        ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, picture.values.data());
    }
    return ok ? std::string() : in->geterror();
}

int version() {
    return OIIO::openimageio_version();
}

}  // namespace
}  // namespace whitted

extern "C" const whitted::ImageCodec* whitted_image_codec() {
    static const whitted::ImageCodec codec{whitted::encode, whitted::decode, whitted::version};
    return &codec;
}
