#include "image/zlib_stripes.h"

#include <zlib.h>

#include <algorithm>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>

#include "base/parallel_for.h"
#include "base/uninitialised_allocator.h"

namespace whitted {
namespace {

using Bytes = std::vector<unsigned char, UninitialisedAllocator<unsigned char>>;

// Deflate's window: what a stripe may refer back to.
constexpr std::size_t kWindow = std::size_t(1) << 15;
// Stripes of at least this much, so that starting a stream is nothing beside
// compressing it; four a thread, so that a fast stripe (a sky) and a slow one
// (a floor) even out among the threads; at most the last, for deflate's
// 32-bit counts.
constexpr std::size_t kSmallestStripe = std::size_t(1) << 18;
constexpr std::size_t kStripesPerThread = 4;
constexpr std::size_t kLargestStripe = std::size_t(1) << 30;

struct Stripe {
    std::size_t firstRow = 0, endRow = 0;
    Bytes deflated;  // raw deflate, ending on a byte boundary
    uLong adler = 0;
};

[[noreturn]] void refused(int code, const char* what) {
    if (code == Z_MEM_ERROR) throw std::bad_alloc();
    throw std::runtime_error(std::string("zlib could not ") + what + " (" + std::to_string(code) +
                             ")");
}

// Raw deflate of the stripe's rows, primed with the window of rows before it,
// ended with a sync flush unless it is the last.
void deflateStripe(std::size_t rowBytes, const RowWriter& writeRow, int level, bool last,
                   Stripe& s) {
    const std::size_t primedRows =
        s.firstRow == 0 ? 0 : std::min(s.firstRow, (kWindow + rowBytes - 1) / rowBytes);
    Bytes rows((primedRows + s.endRow - s.firstRow) * rowBytes);
    for (std::size_t r = s.firstRow - primedRows; r < s.endRow; ++r)
        writeRow(r, rows.data() + (r + primedRows - s.firstRow) * rowBytes);
    const unsigned char* own = rows.data() + primedRows * rowBytes;
    const std::size_t length = (s.endRow - s.firstRow) * rowBytes;
    const std::size_t primed = std::min(primedRows * rowBytes, kWindow);

    z_stream z{};
    if (const int code = deflateInit2(&z, level, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY))
        refused(code, "start");
    if (primed > 0) deflateSetDictionary(&z, own - primed, uInt(primed));
    // deflateBound() allows for a stream's end; a sync flush's empty block is
    // 5 bytes more.
    s.deflated.resize(deflateBound(&z, uLong(length)) + 16);
    z.next_in = const_cast<Bytef*>(own);
    z.avail_in = uInt(length);
    z.next_out = s.deflated.data();
    z.avail_out = uInt(s.deflated.size());
    const int done = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
    s.deflated.resize(s.deflated.size() - z.avail_out);
    deflateEnd(&z);
    if (done != (last ? Z_STREAM_END : Z_OK) || z.avail_in != 0) refused(done, "compress");
    s.adler = adler32(adler32(0, nullptr, 0), own, uInt(length));
}

std::vector<Stripe> stripesOf(std::size_t rows, std::size_t rowBytes, int threads) {
    const std::size_t wanted = std::size_t(threads) * kStripesPerThread;
    const std::size_t fewest = (kSmallestStripe + rowBytes - 1) / rowBytes;
    const std::size_t most = std::max<std::size_t>(1, kLargestStripe / rowBytes);
    const std::size_t length = std::min(most, std::max(fewest, (rows + wanted - 1) / wanted));
    std::vector<Stripe> stripes;
    for (std::size_t first = 0; first < rows || stripes.empty(); first += length)
        stripes.push_back({first, std::min(rows, first + length), {}, 0});
    return stripes;
}

// The two bytes before a zlib stream (RFC 1950) as zlib writes them: deflate
// with a 32 KB window, the level's class, and the pair a multiple of 31.
void appendHeader(int level, std::vector<unsigned char>& stream) {
    const int levelClass = level < 2 ? 0 : level < 6 ? 1 : level == 6 ? 2 : 3;
    const unsigned header = 0x7800u | unsigned(levelClass << 6);
    stream.push_back(0x78);
    stream.push_back(static_cast<unsigned char>((header + (31 - header % 31) % 31) & 0xff));
}

}  // namespace

std::vector<unsigned char> zlibOfRows(std::size_t rows, std::size_t rowBytes,
                                      const RowWriter& writeRow, int level, int threads) {
    threads = resolveThreadCount(threads);
    if (rowBytes == 0) rows = 0;
    std::vector<Stripe> stripes = stripesOf(rows, std::max<std::size_t>(1, rowBytes), threads);
    std::vector<std::exception_ptr> failed(stripes.size());
    forChunks(
        int(stripes.size()), threads,
        [&](int i) {
            try {
                deflateStripe(rowBytes, writeRow, level, i + 1 == int(stripes.size()), stripes[i]);
            } catch (...) {  // a helper thread must not throw
                failed[i] = std::current_exception();
            }
        },
        1);
    for (const std::exception_ptr& e : failed)
        if (e) std::rethrow_exception(e);
    std::vector<unsigned char> stream;
    appendHeader(level, stream);
    uLong adler = adler32(0, nullptr, 0);
    for (const Stripe& s : stripes) {
        stream.insert(stream.end(), s.deflated.begin(), s.deflated.end());
        adler = adler32_combine(adler, s.adler, z_off_t((s.endRow - s.firstRow) * rowBytes));
    }
    for (int shift = 24; shift >= 0; shift -= 8) stream.push_back((adler >> shift) & 0xff);
    return stream;
}

}  // namespace whitted
