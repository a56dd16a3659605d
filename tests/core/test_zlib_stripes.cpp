// Tests for core/image/zlib_stripes.*: the stream made on several threads is
// one zlib stream, read back byte for byte by zlib itself (which checks its
// checksum), whatever the threads, and as small as one stream made on one
// thread: each stripe refers back into the one before.
#include <zlib.h>

#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "image/zlib_stripes.h"

namespace whitted {
namespace {

constexpr std::size_t kRowBytes = 3 * 1280 + 1;

// Rows of one random row repeated: all but the first compress to nearly
// nothing, unless a stripe cannot see the rows before it.
std::vector<unsigned char> repeatedRandomRow(std::size_t rows) {
    std::mt19937 rng(7);
    std::vector<unsigned char> row(kRowBytes);
    for (unsigned char& b : row) b = static_cast<unsigned char>(rng());
    std::vector<unsigned char> data;
    for (std::size_t r = 0; r < rows; ++r) data.insert(data.end(), row.begin(), row.end());
    return data;
}

std::vector<unsigned char> compressed(const std::vector<unsigned char>& data, int threads) {
    const std::size_t rows = data.size() / kRowBytes;
    return zlibOfRows(
        rows, kRowBytes,
        [&](std::size_t r, unsigned char* out) {
            std::memcpy(out, data.data() + r * kRowBytes, kRowBytes);
        },
        5, threads);
}

std::vector<unsigned char> inflated(const std::vector<unsigned char>& stream, std::size_t size) {
    std::vector<unsigned char> out(size + 1);
    uLongf length = out.size();
    EXPECT_EQ(uncompress(out.data(), &length, stream.data(), uLong(stream.size())), Z_OK);
    out.resize(length);
    return out;
}

TEST(ZlibStripes, OneStreamReadByZlib_WhateverTheThreads) {
    std::mt19937 rng(3);
    std::vector<unsigned char> data(kRowBytes * 720);
    for (std::size_t i = 0; i < data.size(); ++i)  // runs and noise, as in a picture
        data[i] = static_cast<unsigned char>(i / 97 % 7 == 0 ? rng() : i / 5000);
    for (int threads : {1, 2, 3, 8}) {
        const std::vector<unsigned char> stream = compressed(data, threads);
        EXPECT_EQ(inflated(stream, data.size()), data) << threads << " threads";
    }
    EXPECT_EQ(inflated(compressed({}, 2), 0), std::vector<unsigned char>{});
}

TEST(ZlibStripes, EachStripeSeesTheRowsBeforeIt_AsSmallAsOneStream) {
    const std::vector<unsigned char> data = repeatedRandomRow(720);
    std::vector<unsigned char> single(compressBound(uLong(data.size())));
    uLongf length = single.size();
    ASSERT_EQ(compress2(single.data(), &length, data.data(), uLong(data.size()), 5), Z_OK);
    const std::vector<unsigned char> striped = compressed(data, 8);
    EXPECT_EQ(inflated(striped, data.size()), data);
    // Unprimed, each of the 11 stripes would hold the 3.8 KB row again.
    EXPECT_LT(striped.size(), length + 1024) << "one stream: " << length << " bytes";
}

}  // namespace
}  // namespace whitted
