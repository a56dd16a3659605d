// Tests for core/image_io.*: round trips through every format with the tolerance
// each format allows (SPEC §5), the metadata in the files, and failed writes that
// leave nothing behind.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "image/exr_codec.h"
#include "image/image_io.h"
#include "image/png_encode.h"
#include "image/srgb.h"
#include "support/test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

// 8x4 with exact zeros, values above 1 and a spread in between.
Image knownImage() {
    Image img(8, 4);
    const float values[] = {0.0f, 1.0f, 0.5f,  0.25f, 0.01f, 0.002f, 0.75f, 0.18f,
                            2.0f, 4.5f, 1.25f, 0.9f,  0.33f, 0.001f, 0.6f,  16.0f};
    for (size_t k = 0; k < img.rgb.size(); ++k) img.rgb[k] = values[(k * 7 + k / 5) % 16];
    // Pixel (0,0) all zero and pixel (1,0) all above 1, whatever the pattern gives.
    img.pixel(0, 0)[0] = img.pixel(0, 0)[1] = img.pixel(0, 0)[2] = 0.0f;
    img.pixel(1, 0)[0] = 1.5f;
    img.pixel(1, 0)[1] = 3.0f;
    img.pixel(1, 0)[2] = 100.0f;
    return img;
}

// A gradient that is smooth once sRGB-encoded (linear = t^2.2 for t in [0.1, 0.9]),
// for the lossy format: a linear ramp from 0 jumps 34 codes in its first pixel.
Image smoothImage() {
    Image img(64, 48);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            const float u = 0.1f + 0.8f * x / 63.0f, v = 0.1f + 0.8f * y / 47.0f;
            float* p = img.pixel(x, y);
            p[0] = std::pow(u, 2.2f);
            p[1] = std::pow(v, 2.2f);
            p[2] = std::pow(0.5f * (u + v), 2.2f);
        }
    return img;
}

ImageMetadata metadata() {
    RenderSettings s;
    s.width = 97;
    s.height = 61;
    s.samplesPerPixel = 5;
    s.maxDepth = 3;
    s.precision = Precision::Double;
    return makeImageMetadata(s, 1.25, "whitted-tests");
}

Image roundTrip(const Image& img, const TempDir& dir, const std::string& name) {
    const fs::path file = dir / name;
    writeImage(img, file, metadata());
    EXPECT_TRUE(fs::exists(file)) << name;
    return readImage(file);
}

TEST(ImageIo, FloatTiffAndExr_RoundTripExactly) {
    TempDir dir;
    const Image img = knownImage();
    for (const char* name : {"a.tif", "a.tiff", "a.exr", "UPPER.EXR"}) {
        const Image back = roundTrip(img, dir, name);
        ASSERT_EQ(back.width, 8) << name;
        ASSERT_EQ(back.height, 4) << name;
        EXPECT_EQ(back.rgb, img.rgb) << name << ": float formats must be exact";
    }
}

TEST(ImageIo, Hdr_RoundTripsWithinOnePercentOfPixelMaximum) {
    // RGBE shares one exponent per pixel: 8-bit mantissas are within 1/256 of the
    // pixel's largest channel, so the tolerance is 1% of that channel.
    TempDir dir;
    const Image img = knownImage();
    const Image back = roundTrip(img, dir, "a.hdr");
    ASSERT_EQ(back.width, 8);
    ASSERT_EQ(back.height, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            const float* a = img.pixel(x, y);
            const float* b = back.pixel(x, y);
            const float peak = std::max({a[0], a[1], a[2]});
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(b[c], a[c], 0.01f * peak) << "pixel " << x << "," << y << " ch " << c;
        }
    EXPECT_EQ(back.pixel(0, 0)[0], 0.0f);
    EXPECT_NEAR(back.pixel(1, 0)[2], 100.0f, 1.0f) << "HDR keeps values above 1";
}

TEST(ImageIo, Png_RoundTripsWithinOneSrgbStepAndClampsAboveOne) {
    TempDir dir;
    const Image img = knownImage();
    const Image back = roundTrip(img, dir, "a.png");
    ASSERT_EQ(back.width, 8);
    ASSERT_EQ(back.height, 4);
    for (size_t k = 0; k < img.rgb.size(); ++k) {
        const float want = std::min(img.rgb[k], 1.0f);
        // Compared in the encoded domain: within one 8-bit step (plus rounding slack).
        EXPECT_NEAR(srgbEncode(back.rgb[k]), srgbEncode(want), 1.0f / 255 + 1e-6f)
            << "component " << k << ": wrote " << img.rgb[k] << ", read " << back.rgb[k];
        if (img.rgb[k] >= 1.0f) {
            EXPECT_EQ(back.rgb[k], 1.0f) << "component " << k;
        }
        if (img.rgb[k] == 0.0f) {
            EXPECT_EQ(back.rgb[k], 0.0f) << "component " << k;
        }
    }
}

TEST(ImageIo, Png_StoresSrgbCodesNotLinear) {
    // Linear 0.5 is sRGB code round(255 * 0.7353569) = 188 (linear would be 128);
    // linear 0.18 is code 118; 0.002 is 12.92 * 0.002 * 255 = 6.6 -> 7.
    TempDir dir;
    Image img(3, 1);
    img.pixel(0, 0)[0] = img.pixel(0, 0)[1] = img.pixel(0, 0)[2] = 0.5f;
    img.pixel(1, 0)[0] = img.pixel(1, 0)[1] = img.pixel(1, 0)[2] = 0.18f;
    img.pixel(2, 0)[0] = img.pixel(2, 0)[1] = img.pixel(2, 0)[2] = 0.002f;
    const fs::path file = dir / "codes.png";
    writeImage(img, file, metadata());
    auto in = OIIO::ImageInput::open(file.string());
    ASSERT_TRUE(in) << OIIO::geterror();
    ASSERT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
    // The sRGB chunk, so that viewers show the codes as they are.
    EXPECT_EQ(in->spec().get_string_attribute("oiio:ColorSpace"), "sRGB");
    const int channels = in->spec().nchannels;
    std::vector<unsigned char> codes(size_t(3) * channels);
    ASSERT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, codes.data()));
    EXPECT_EQ(codes[0], 188);
    EXPECT_EQ(codes[size_t(channels)], 118);
    EXPECT_EQ(codes[size_t(2) * channels], 7);
}

// A picture large enough that its rows are compressed in stripes on every
// core (zlib_stripes.h) reads back through OpenImageIO code for code, its
// metadata before the pixels as libpng writes it.
TEST(PngEncode, LargePicture_CompressedInStripes_ReadsBackCodeForCode) {
    CodecPicture picture;
    picture.width = picture.fullWidth = 1280;
    picture.height = picture.fullHeight = 720;
    picture.eightBit = true;
    picture.attributes["Software"] = {"whitted test", {}, {}};
    picture.codes.resize(std::size_t(3) * 1280 * 720);
    for (std::size_t i = 0; i < picture.codes.size(); ++i)  // smooth parts and noise
        picture.codes[i] = static_cast<unsigned char>(i % 3840 / 16 + (i * 2654435761u >> 29));
    std::vector<unsigned char> encoded;
    ASSERT_EQ(encodePng(picture, picture.codes.data(), encoded), "");
    TempDir dir;
    const fs::path file = dir / "large.png";
    test::writeFile(file, std::string(encoded.begin(), encoded.end()));
    auto in = OIIO::ImageInput::open(file.string());
    ASSERT_TRUE(in) << OIIO::geterror();
    EXPECT_EQ(in->spec().get_string_attribute("Software"), "whitted test");
    std::vector<unsigned char> codes(picture.codes.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, codes.data())) << in->geterror();
    EXPECT_TRUE(codes == picture.codes);
}

TEST(ImageIo, Jpeg_RoundTripsSmoothImageWithinLooseTolerance) {
    // Lossy (quality 95, 4:2:0 chroma): in the encoded domain, at most 6 8-bit steps
    // anywhere and 1.5 on average. (Measured: 3.4 and 0.66.)
    TempDir dir;
    const Image img = smoothImage();
    for (const char* name : {"a.jpg", "a.jpeg"}) {
        const Image back = roundTrip(img, dir, name);
        ASSERT_EQ(back.width, 64) << name;
        ASSERT_EQ(back.height, 48) << name;
        double worst = 0, sum = 0;
        for (size_t k = 0; k < img.rgb.size(); ++k) {
            const double d = std::fabs(srgbEncode(back.rgb[k]) - srgbEncode(img.rgb[k]));
            worst = std::max(worst, d);
            sum += d;
        }
        EXPECT_LE(worst, 6.0 / 255) << name;
        EXPECT_LE(sum / img.rgb.size(), 1.5 / 255) << name;
    }
}

TEST(ImageIo, WrittenFiles_DescribeTheRenderSettings) {
    TempDir dir;
    const Image img = knownImage();
    // HDR has no place for a free-text description.
    for (const char* name : {"m.png", "m.jpg", "m.tif", "m.exr"}) {
        const fs::path file = dir / name;
        writeImage(img, file, metadata());
        auto in = OIIO::ImageInput::open(file.string());
        ASSERT_TRUE(in) << name << ": " << OIIO::geterror();
        const std::string description = in->spec().get_string_attribute("ImageDescription");
        EXPECT_NE(description.find("97x61"), std::string::npos) << name << ": " << description;
        EXPECT_NE(description.find("5 samples"), std::string::npos) << name << ": " << description;
        EXPECT_NE(description.find("double"), std::string::npos) << name << ": " << description;
        EXPECT_EQ(in->spec().get_string_attribute("Software"), "whitted-tests") << name;
    }
}

TEST(ImageIo, WriteIntoMissingDirectory_ThrowsAndLeavesNothing) {
    TempDir dir;
    const fs::path file = dir / "missing" / "out.png";
    EXPECT_THROW(writeImage(knownImage(), file, metadata()), ImageIoError);
    EXPECT_FALSE(fs::exists(dir / "missing"));
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

// libpng refuses what PNG cannot hold by jumping out of its own code: the
// reason comes back as text, with libpng's warning that says what was wrong.
TEST(PngEncode, WhatLibpngRefuses_ComesBackAsItsReason) {
    CodecPicture picture;
    picture.width = 0;
    picture.height = 4;
    picture.eightBit = true;
    picture.codes.assign(12, 0);
    std::vector<unsigned char> encoded;
    const std::string reason = encodePng(picture, picture.codes.data(), encoded);
    EXPECT_NE(reason.find("width"), std::string::npos) << reason;
    picture.width = 1;
    encoded.clear();
    EXPECT_EQ(encodePng(picture, picture.codes.data(), encoded), "");
    EXPECT_GT(encoded.size(), 8u);
    EXPECT_EQ(std::string(encoded.begin() + 1, encoded.begin() + 4), "PNG");
}

// OpenEXR's refusal (here of a picture with no pixels) comes back as its text.
TEST(ExrEncode, WhatOpenExrRefuses_ComesBackAsItsReason) {
    CodecPicture picture;
    picture.width = picture.fullWidth = 0;
    picture.height = picture.fullHeight = 4;
    const std::vector<float> values(12, 0.5f);
    std::vector<unsigned char> encoded;
    EXPECT_FALSE(encodeExr(picture, values.data(), encoded).empty());
    picture.width = picture.fullWidth = 1;
    encoded.clear();
    EXPECT_EQ(encodeExr(picture, values.data(), encoded), "");
    ASSERT_GT(encoded.size(), 4u);
    EXPECT_EQ(encoded[0], 0x76);  // OpenEXR's magic number, 20000630
    EXPECT_EQ(encoded[1], 0x2f);
}

TEST(ImageIo, WriteWithUnknownExtension_ThrowsNamingFileAndLeavesNothing) {
    TempDir dir;
    for (const char* name : {"out.bmp", "out", "out.png.txt"}) {
        const fs::path file = dir / name;
        try {
            writeImage(knownImage(), file, metadata());
            ADD_FAILURE() << name << ": written";
        } catch (const ImageIoError& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
        EXPECT_TRUE(dir.entries().empty()) << name << ": " << test::joined(dir.entries());
    }
}

// A full disk: out.png is a link to /dev/full, so every write fails with
// ENOSPC. The export must say so, leave nothing beside it, and above all not
// rename a temporary over the link's target (as root that would replace the
// /dev/full device node).
TEST(ImageIo, WriteToFullDisk_ThrowsNoSpaceAndLeavesDeviceAndDirectoryAlone) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
    TempDir dir;
    for (const char* name : {"out.png", "out.exr", "out.jpg"}) {
        const fs::path link = dir / name;
        fs::create_symlink("/dev/full", link);
        try {
            writeImage(smoothImage(), link, metadata());
            ADD_FAILURE() << name << ": written to a full disk";
        } catch (const ImageIoError& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
        EXPECT_TRUE(fs::is_symlink(link)) << name;
        EXPECT_TRUE(fs::is_character_file("/dev/full")) << "the device node was replaced";
        fs::remove(link);
        EXPECT_TRUE(dir.entries().empty()) << name << ": " << test::joined(dir.entries());
    }
}

// A directory the process may not write to. Root may write anywhere, so the
// test checks the outcome rather than the refusal: either a clear error and no
// file, or (as root) the whole image.
TEST(ImageIo, WriteIntoReadOnlyDirectory_FailsCleanlyOrWritesWholeFile) {
    TempDir dir;
    const fs::path locked = dir / "locked";
    fs::create_directory(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    const fs::path file = locked / "out.png";
    try {
        writeImage(knownImage(), file, metadata());
        EXPECT_EQ(readImage(file).width, knownImage().width);  // root: written whole
    } catch (const ImageIoError& e) {
        EXPECT_NE(std::string(e.what()).find("out.png"), std::string::npos) << e.what();
        EXPECT_FALSE(fs::exists(file));
    }
    fs::permissions(locked, fs::perms::owner_all);
    for (const auto& e : fs::directory_iterator(locked))
        EXPECT_EQ(e.path().filename(), "out.png") << "a temporary was left behind";
}

TEST(ImageIo, OverwritingExistingFile_ReplacesItAndLeavesNoTemporaries) {
    TempDir dir;
    const fs::path file = dir / "out.exr";
    Image first = knownImage();
    writeImage(first, file, metadata());
    Image second = smoothImage();
    writeImage(second, file, metadata());
    EXPECT_EQ(readImage(file).rgb, second.rgb);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.exr"}) << test::joined(dir.entries());
}

TEST(ImageIo, ReadMissingOrNonImageFile_ThrowsImageIoError) {
    TempDir dir;
    EXPECT_THROW(readImage(dir / "none.png"), ImageIoError);
    test::writeFile(dir / "text.png", "this is not a png");
    EXPECT_THROW(readImage(dir / "text.png"), ImageIoError);
}

// `values` (floats, spec.nchannels a pixel) written to `file` by OpenImageIO
// in the format spec asks for, as another program would write it.
bool writtenByOpenImageIO(const std::string& file, const OIIO::ImageSpec& spec,
                          const std::vector<float>& values) {
    auto out = OIIO::ImageOutput::create(file);
    return out && out->open(file, spec) && out->write_image(OIIO::TypeDesc::FLOAT, values.data()) &&
           out->close();
}

// An OpenEXR file as another program writes it: half floats, an alpha
// channel, its pixels a window of a display window that does not start at 0.
// Read without the plug-in (decodeExr()), it gives the same as OpenImageIO.
TEST(ImageIo, ExrOfHalfRgbaInAWindow_ReadsAsOpenImageIOReadsIt) {
    TempDir dir;
    const fs::path file = dir / "half.exr";
    OIIO::ImageSpec spec(5, 3, 4, OIIO::TypeDesc::HALF);
    spec.x = 12;
    spec.y = 7;
    spec.full_x = 10;
    spec.full_y = 5;
    spec.full_width = 20;
    spec.full_height = 10;
    spec.attribute("ImageDescription", "from elsewhere");
    spec.attribute("whitted:max_depth", 7);
    std::vector<float> rgba(5 * 3 * 4);
    for (size_t k = 0; k < rgba.size(); ++k) rgba[k] = 0.1f * float(k) + 0.013f;
    ASSERT_TRUE(writtenByOpenImageIO(file.string(), spec, rgba)) << OIIO::geterror();

    const std::optional<CodecPicture> mine = decodeExr(file.string());
    ASSERT_TRUE(mine);
    const ImagePart part = readImagePart(file);
    EXPECT_EQ(part.window.x, 2);
    EXPECT_EQ(part.window.y, 2);
    EXPECT_EQ(part.window.width, 5);
    EXPECT_EQ(part.window.height, 3);
    EXPECT_EQ(part.fullWidth, 20);
    EXPECT_EQ(part.fullHeight, 10);
    EXPECT_EQ(part.metadata.description, "from elsewhere");
    EXPECT_EQ(part.metadata.settings.maxDepth, 7);
    auto in = OIIO::ImageInput::open(file.string());
    ASSERT_TRUE(in);
    std::vector<float> theirs(rgba.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, theirs.data()));
    for (size_t p = 0; p < 15; ++p)
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(part.image.rgb[p * 3 + c], theirs[p * 4 + c]) << p << "," << c;
            EXPECT_NEAR(part.image.rgb[p * 3 + c], rgba[p * 4 + c], 1e-3f * rgba[p * 4 + c]);
        }
}

// What OpenEXR cannot read or holds no RGB goes to the plug-in, which
// refuses it in its words, naming the file.
TEST(ImageIo, ExrThatIsNotOne_IsRefusedNamingTheFile) {
    TempDir dir;
    test::writeFile(dir / "text.exr", "this is not an exr");
    EXPECT_FALSE(decodeExr((dir / "text.exr").string()));
    try {
        readImage(dir / "text.exr");
        ADD_FAILURE() << "read";
    } catch (const ImageIoError& e) {
        EXPECT_NE(std::string(e.what()).find("text.exr"), std::string::npos) << e.what();
    }
    OIIO::ImageSpec grey(4, 4, 1, OIIO::TypeDesc::FLOAT);
    grey.channelnames = {"Y"};
    const std::string greyFile = (dir / "grey.exr").string();
    ASSERT_TRUE(writtenByOpenImageIO(greyFile, grey, std::vector<float>(16, 0.5f)))
        << OIIO::geterror();
    EXPECT_FALSE(decodeExr(greyFile));
    EXPECT_THROW(readImage(greyFile), ImageIoError);  // the plug-in's: fewer than 3 channels
}

TEST(ImageIo, FormatTable_KnowsTheFiveFormatsCaseInsensitively) {
    EXPECT_EQ(imageFormatFor("a.png")->format, ImageFormat::Png);
    EXPECT_EQ(imageFormatFor("a.JPG")->format, ImageFormat::Jpeg);
    EXPECT_EQ(imageFormatFor("a.jpeg")->format, ImageFormat::Jpeg);
    EXPECT_EQ(imageFormatFor("a.Tif")->format, ImageFormat::Tiff);
    EXPECT_EQ(imageFormatFor("a.exr")->format, ImageFormat::Exr);
    EXPECT_EQ(imageFormatFor("a.hdr")->format, ImageFormat::Hdr);
    EXPECT_FALSE(imageFormatFor("a.bmp"));
    EXPECT_FALSE(imageFormatFor("png"));
    EXPECT_TRUE(imageFormatFor("a.exr")->isFloat);
    EXPECT_FALSE(imageFormatFor("a.png")->isFloat);
}

}  // namespace
}  // namespace whitted
