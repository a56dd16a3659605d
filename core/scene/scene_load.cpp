// Scene files to scenes: the size guard, then the text streamed to the reader
// a chunk at a time with progress reports, so that neither the file's text
// nor its DOM is ever held whole.
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <vector>

#include "scene/scene_io.h"
#include "scene/scene_json.h"

namespace whitted {
namespace fs = std::filesystem;

namespace {

constexpr std::uintmax_t kMB = std::uintmax_t(1) << 20;

// Hands the parser the file 1 MB at a time and reports each chunk.
class FileChunks : public detail::ChunkedText {
  public:
    FileChunks(std::ifstream& in, std::uintmax_t total, const LoadProgress& progress)
        : in_(in), total_(total), progress_(progress), chunk_(kMB) {}
    bool failed() const { return in_.bad(); }
    std::uintmax_t size() const override { return total_; }

    std::string_view next() override {
        in_.read(chunk_.data(), std::streamsize(chunk_.size()));
        const auto n = std::size_t(in_.gcount());
        done_ += n;
        if (n > 0 && progress_) progress_(done_, std::max(done_, total_));
        return {chunk_.data(), n};
    }

  private:
    std::ifstream& in_;
    std::uintmax_t total_, done_ = 0;
    const LoadProgress& progress_;
    std::vector<char> chunk_;
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
    FileChunks chunks(in, noSize ? 0 : size, progress);
    try {
        Scene scene = detail::parseScene(chunks, file.string());
        if (!chunks.failed()) return scene;
    } catch (const SceneError&) {
        if (!chunks.failed()) throw;
    }
    throw SceneError(file.string(), "", "cannot read file");
}

}  // namespace whitted
