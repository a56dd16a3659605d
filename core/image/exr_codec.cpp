#include "image/exr_codec.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <cstring>
#include <exception>

#include "base/parallel_for.h"

namespace whitted {
namespace {

// The file in memory: OpenEXR seeks back to write the table of line offsets.
class MemoryStream : public Imf::OStream {
  public:
    explicit MemoryStream(std::vector<unsigned char>& bytes)
        : Imf::OStream("memory"), bytes_(bytes) {}
    void write(const char c[], int n) override {
        if (bytes_.size() < position_ + n) bytes_.resize(position_ + n);
        std::memcpy(bytes_.data() + position_, c, n);
        position_ += n;
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = position; }

  private:
    std::vector<unsigned char>& bytes_;
    uint64_t position_ = 0;
};

// (De)compression is most of the writing and reading, and OpenEXR's pool of
// threads for it is empty until it is given a size: one thread for each core
// this process may run on, as OpenImageIO gave it one for each core.
void useEveryCore() {
    static const bool pooled = [] {
        Imf::setGlobalThreadCount(resolveThreadCount(0));
        return true;
    }();
    (void)pooled;
}

// The R, G and B channels of `window`, interleaved at `values` row by row.
Imf::FrameBuffer rgbFrame(const float* values, const Imath::Box2i& window) {
    const std::size_t pixel = 3 * sizeof(float);
    const std::size_t row = pixel * std::size_t(window.max.x - window.min.x + 1);
    Imf::FrameBuffer frame;
    const char* names[] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
        frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, values + c, window, pixel, row));
    return frame;
}

Imf::Header headerOf(const CodecPicture& picture) {
    const Imath::Box2i display({0, 0}, {picture.fullWidth - 1, picture.fullHeight - 1});
    const Imath::Box2i data({picture.x, picture.y},
                            {picture.x + picture.width - 1, picture.y + picture.height - 1});
    Imf::Header header(display, data);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* channel : {"R", "G", "B"})
        header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
    for (const auto& [name, value] : picture.attributes) {
        if (name == "oiio:ColorSpace") continue;
        const std::string key = name == "ImageDescription" ? "comments" : name;
        if (value.integer)
            header.insert(key, Imf::IntAttribute(*value.integer));
        else if (value.real)
            header.insert(key, Imf::FloatAttribute(*value.real));
        else
            header.insert(key, Imf::StringAttribute(value.text));
    }
    return header;
}

// An attribute as the plug-in's attributeOf() gives it: a number also as
// text, an int also as a float.
std::optional<CodecAttribute> attributeOf(const Imf::Attribute& a) {
    if (const auto* t = dynamic_cast<const Imf::StringAttribute*>(&a))
        return CodecAttribute{t->value(), std::nullopt, std::nullopt};
    if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&a))
        return CodecAttribute{std::to_string(i->value()), i->value(), float(i->value())};
    if (const auto* f = dynamic_cast<const Imf::FloatAttribute*>(&a))
        return CodecAttribute{std::to_string(f->value()), std::nullopt, f->value()};
    return std::nullopt;  // boxes, chromaticities...: nothing the renderer records
}

bool hasRgb(const Imf::Header& header) {
    const Imf::ChannelList& channels = header.channels();
    return channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
}

}  // namespace

std::optional<CodecPicture> decodeExr(const std::string& fileName) {
    try {
        useEveryCore();
        Imf::InputFile file(fileName.c_str());
        const Imf::Header& header = file.header();
        if (!hasRgb(header)) return std::nullopt;
        const Imath::Box2i data = header.dataWindow(), display = header.displayWindow();
        CodecPicture p;
        p.width = data.max.x - data.min.x + 1;
        p.height = data.max.y - data.min.y + 1;
        p.x = data.min.x - display.min.x;
        p.y = data.min.y - display.min.y;
        p.fullWidth = display.max.x - display.min.x + 1;
        p.fullHeight = display.max.y - display.min.y + 1;
        p.values.resize(std::size_t(p.width) * p.height * 3);
        file.setFrameBuffer(rgbFrame(p.values.data(), data));
        file.readPixels(data.min.y, data.max.y);
        for (auto it = header.begin(); it != header.end(); ++it)
            if (auto a = attributeOf(it.attribute()))
                p.attributes[std::strcmp(it.name(), "comments") == 0 ? "ImageDescription"
                                                                     : it.name()] = std::move(*a);
        return p;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

std::string encodeExr(const CodecPicture& picture, const float* values,
                      std::vector<unsigned char>& encoded) {
    if (picture.eightBit || picture.channels != 3) return "OpenEXR is written from RGB floats";
    try {
        const Imf::Header header = headerOf(picture);
        MemoryStream stream(encoded);
        useEveryCore();
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(rgbFrame(values, header.dataWindow()));
        file.writePixels(picture.height);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace whitted
