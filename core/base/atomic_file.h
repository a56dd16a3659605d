// Replace a file all at once: write beside it, flush to disk, rename over it.
// A failure at any step leaves the old file (or no file) and no temporary behind.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace whitted {

// Calls `write` with a temporary path in the same directory that keeps the
// target's extension (so format-by-extension writers such as OpenImageIO still
// work), then renames it to `target`. If `write` throws, or the rename fails, the
// temporary is removed and the exception propagates. A target that is a device
// or a pipe (/dev/full) is written directly instead: there is nothing to replace.
// Writes every byte to `file` (created or truncated) with checked system
// calls, or throws std::system_error with the reason ("No space left on
// device"); stream libraries and image writers lose such errors.
void writeAllBytes(const std::filesystem::path& file, std::string_view bytes);

void replaceFileAtomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& temp)>& write);

// `target` replaced at once by `text` (the two above). Throws std::system_error
// whose what() names the target, not the temporary: "<target>: <reason>".
void replaceFileWithText(const std::filesystem::path& target, std::string_view text);

}  // namespace whitted
