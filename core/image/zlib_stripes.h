// A zlib stream made on several threads, as pigz makes one: the rows are cut
// into stripes, each compressed by its own deflate stream primed with the 32 KB
// before it (so the ratio is that of one stream), the stripes but the last
// ended on a byte boundary (a sync flush), and their checksums combined. zlib
// itself compresses on one thread, and a 1280x720 PNG's compression was a
// third of the whole whitted-render run that wrote it.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace whitted {

// Writes row `row`'s rowBytes bytes at `out`; called from several threads at
// once, and for some rows more than once.
using RowWriter = std::function<void(std::size_t row, unsigned char* out)>;

// The bytes of `rows` rows, each written by writeRow() when its stripe is
// compressed (no copy of them all is made), as one zlib stream at zlib's
// `level`, on up to `threads` threads (0: every core this process may run
// on). Throws std::bad_alloc when memory runs out, and std::runtime_error with
// what zlib refused for anything else.
std::vector<unsigned char> zlibOfRows(std::size_t rows, std::size_t rowBytes,
                                      const RowWriter& writeRow, int level, int threads = 0);

}  // namespace whitted
