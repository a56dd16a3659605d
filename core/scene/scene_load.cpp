// Scene files to scenes: the size guard, then the whole text read into memory
// a megabyte at a time with progress reports, with the room after it that the
// fast reader needs (scene_fast_read.h).
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <vector>

#include "base/uninitialised_allocator.h"
#include "scene/scene_fast_read.h"
#include "scene/scene_io.h"
#include "scene/scene_json.h"

namespace whitted {
namespace fs = std::filesystem;

namespace {

constexpr std::uintmax_t kMB = std::uintmax_t(1) << 20;

// Every byte is written by the read before it is read: no zeroing of 150 MB.
using Bytes = std::vector<char, UninitialisedAllocator<char>>;

// The whole pages of [p, p + bytes) made present now, in one call: a megabyte
// of new pages a call, in place of a fault a page as the read fills them
// (the 1M-ball file read in 84 ms instead of 96 to 113, a test program).
// Only a hint: where the kernel lacks it, the read faults them in.
void populatePages(char* p, std::size_t bytes) {
    const auto page = std::uintptr_t(sysconf(_SC_PAGE_SIZE));
    const std::uintptr_t first = (std::uintptr_t(p) + page - 1) & ~(page - 1);
    const std::uintptr_t end = (std::uintptr_t(p) + bytes) & ~(page - 1);
    if (end > first) madvise(reinterpret_cast<void*>(first), end - first, MADV_POPULATE_WRITE);
}

std::string megabytes(std::uintmax_t bytes) {
    return std::to_string((bytes + kMB - 1) / kMB) + " MB";
}

// The stream's text from here to its end, then fastReadPadding() spaces;
// `expected` its length as far as known (0: unknown). Progress a megabyte at
// a time. Nothing when the stream failed.
std::optional<Bytes> readPadded(std::ifstream& in, std::uintmax_t expected, std::uintmax_t limit,
                                const LoadProgress& progress, std::size_t& size) {
    const std::size_t padding = detail::fastReadPadding();
    Bytes text(std::size_t(expected) + padding);
    size = 0;
    for (;;) {
        if (size + padding == text.size()) {  // full: at the end, or the size was not known
            if (in.peek() == std::ifstream::traits_type::eof()) break;
            text.resize(std::max(2 * size, std::size_t(kMB)) + padding);
        }
        const std::size_t want = std::min(std::size_t(kMB), text.size() - padding - size);
        populatePages(text.data() + size, want);
        in.read(text.data() + size, std::streamsize(want));
        const auto n = std::size_t(in.gcount());
        size += n;
        if (n > 0 && progress) progress(size, std::max<std::uintmax_t>(size, expected));
        if (n < want || size > limit) break;
    }
    if (in.bad()) return std::nullopt;
    std::fill_n(text.data() + size, padding, ' ');
    return text;
}

}  // namespace

SceneFileLimit sceneFileLimit() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    const std::uintmax_t quarter =
        pages > 0 && pageSize > 0 ? std::uintmax_t(pages) * std::uintmax_t(pageSize) / 4 : 0;
    if (quarter < kMinSceneFileLimit) return {kMinSceneFileLimit, "the smallest limit"};
    return {quarter, "a quarter of this machine's memory"};
}

Scene loadScene(const fs::path& file, const LoadProgress& progress, const SceneFileLimit& limit) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SceneError(file.string(), "", "cannot open file");
    std::error_code noSize;
    const std::uintmax_t size = fs::file_size(file, noSize);
    const auto refused = [&](const std::string& howLarge) {
        return SceneError(file.string(), "",
                          "is " + howLarge + "; scene files larger than " + megabytes(limit.bytes) +
                              " (" + limit.why + ") are refused");
    };
    if (!noSize && size > limit.bytes) throw refused(megabytes(size));
    std::size_t length = 0;
    const std::optional<Bytes> text =
        readPadded(in, noSize ? 0 : size, limit.bytes, progress, length);
    if (!text) throw SceneError(file.string(), "", "cannot read file");
    // A pipe, whose size is known only as it is read, or a file that grew.
    if (length > limit.bytes) throw refused("more than " + megabytes(limit.bytes));
    return detail::parseSceneText(text->data(), length, text->size(), file.string());
}

}  // namespace whitted
