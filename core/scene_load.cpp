// Scene files to scenes: the size guard, then the text streamed to the reader
// a chunk at a time with progress reports, so that neither the file's text
// nor its DOM is ever held whole.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <memory>
#include <streambuf>

#include "scene_io.h"
#include "scene_json.h"

namespace whitted {
namespace fs = std::filesystem;

namespace {

constexpr std::uintmax_t kMB = std::uintmax_t(1) << 20;

// Hands the parser the file 1 MB at a time and reports each chunk.
class ChunkedFileBuf : public std::streambuf {
  public:
    ChunkedFileBuf(std::ifstream& in, std::uintmax_t total, const LoadProgress& progress)
        : in_(in), total_(total), progress_(progress) {}
    bool failed() const { return in_.bad(); }

  protected:
    int_type underflow() override {
        in_.read(chunk_.data(), std::streamsize(chunk_.size()));
        const auto n = std::size_t(in_.gcount());
        if (n == 0) return traits_type::eof();
        done_ += n;
        if (progress_) progress_(done_, std::max(done_, total_));
        setg(chunk_.data(), chunk_.data(), chunk_.data() + n);
        return traits_type::to_int_type(chunk_[0]);
    }

  private:
    std::ifstream& in_;
    std::uintmax_t total_, done_ = 0;
    const LoadProgress& progress_;
    std::array<char, kMB> chunk_;
};

std::string megabytes(std::uintmax_t bytes) {
    return std::to_string((bytes + kMB - 1) / kMB) + " MB";
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
    if (!noSize && size > limit.bytes)
        throw SceneError(file.string(), "",
                         "is " + megabytes(size) + "; scene files larger than " +
                             megabytes(limit.bytes) + " (" + limit.why + ") are refused");
    auto chunks = std::make_unique<ChunkedFileBuf>(in, noSize ? 0 : size, progress);
    std::istream text(chunks.get());
    try {
        Scene scene = detail::parseScene(text, file.string());
        if (!chunks->failed()) return scene;
    } catch (const SceneError&) {
        if (!chunks->failed()) throw;
    }
    throw SceneError(file.string(), "", "cannot read file");
}

}  // namespace whitted
