#include "image/exr_encode.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <thread>

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

}  // namespace

std::string encodeExr(const CodecPicture& picture, const float* values,
                      std::vector<unsigned char>& encoded) {
    if (picture.eightBit || picture.channels != 3) return "OpenEXR is written from RGB floats";
    try {
        const Imf::Header header = headerOf(picture);
        Imf::FrameBuffer frame;
        const std::size_t pixel = 3 * sizeof(float), row = pixel * picture.width;
        const char* names[] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c)
            frame.insert(names[c],
                         Imf::Slice::Make(Imf::FLOAT, values + c, header.dataWindow(), pixel, row));
        MemoryStream stream(encoded);
        // Compression is most of the writing, and OpenEXR's pool of threads
        // for it is empty until it is given a size: one thread for each core,
        // as OpenImageIO gave it.
        static const bool pooled = [] {
            Imf::setGlobalThreadCount(
                static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
            return true;
        }();
        (void)pooled;
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(frame);
        file.writePixels(picture.height);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace whitted
