// What the scene file's parts share and nothing else needs: the reader
// (scene_json_read.cpp), the file loader (scene_load.cpp), the writer
// (scene_io.cpp) and the clipboard's fragments (scene_fragment.cpp), which
// write their items exactly as the file does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace whitted::detail {

// `s` as a JSON string literal, quotes and escapes included.
std::string quoted(const std::string& s);

// One element of a list as the scene file writes it: one line, keys in SPEC order.
std::string jsonItem(const Material& m);
std::string jsonItem(const Light& l);
std::string jsonItem(const Sphere& s);

// A list's elements one a line, indented as inside the file's top-level object.
template <typename T>
std::string jsonList(const std::vector<T>& items) {
    if (items.empty()) return "[]";
    std::string out = "[\n";
    for (std::size_t i = 0; i < items.size(); ++i)
        out.append("    ").append(jsonItem(items[i])).append(i + 1 < items.size() ? ",\n" : "\n");
    return out + "  ]";
}

// A top-level object of the given keys and values (already JSON), one a line.
using JsonFields = std::vector<std::pair<const char*, std::string>>;
std::string jsonDocument(const JsonFields& top);

// A text handed over a chunk at a time, for files too large to hold whole.
class ChunkedText {
  public:
    virtual ~ChunkedText() = default;
    // The next chunk, valid until the next call; empty at the end.
    virtual std::string_view next() = 0;
    // The whole text's length as far as known beforehand (0: unknown).
    virtual std::uintmax_t size() const = 0;
};

// The characters of a ChunkedText, as the parser's input iterator. The
// default-constructed iterator is the end. Faster than an std::istream, whose
// per-character sbumpc() cost a tenth of the loading time.
class ChunkIterator {
  public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    ChunkIterator() = default;
    explicit ChunkIterator(ChunkedText& text) : text_(&text) { fill(); }
    const char& operator*() const { return *at_; }
    ChunkIterator& operator++() {
        if (++at_ == end_) fill();
        return *this;
    }
    bool operator==(const ChunkIterator& o) const { return at_ == o.at_; }
    bool operator!=(const ChunkIterator& o) const { return at_ != o.at_; }

  private:
    void fill() {
        const std::string_view chunk = text_->next();
        at_ = chunk.empty() ? nullptr : chunk.data();
        end_ = chunk.empty() ? nullptr : chunk.data() + chunk.size();
    }

    ChunkedText* text_ = nullptr;
    const char* at_ = nullptr;
    const char* end_ = nullptr;
};

// parseScene() reading the text as it goes.
Scene parseScene(ChunkedText& text, const std::string& sourceName);

}  // namespace whitted::detail
