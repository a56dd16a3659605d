#include "base/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace whitted {
namespace fs = std::filesystem;

namespace {

fs::path temporaryBeside(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
    std::string name = ".";
    name.append(target.filename().string())
        .append(".tmp")
        .append(std::to_string(::getpid()))
        .append("-")
        .append(std::to_string(counter++))
        .append(target.extension().string());
    return target.parent_path() / name;
}

// Without this a crash right after the rename could leave an empty file on
// some file systems: the rename reaches the disk before the data does.
void flushToDisk(const fs::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY);
    if (fd < 0) throw std::system_error(errno, std::generic_category(), file.string());
    const int rc = ::fsync(fd);
    const int err = errno;
    ::close(fd);
    if (rc != 0) throw std::system_error(err, std::generic_category(), file.string());
}

}  // namespace

void writeAllBytes(const fs::path& file, std::string_view bytes) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throw std::system_error(errno, std::generic_category(), file.string());
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int err = n < 0 ? errno : ENOSPC;
            ::close(fd);
            throw std::system_error(err, std::generic_category(), file.string());
        }
        done += std::size_t(n);
    }
    if (::close(fd) != 0) throw std::system_error(errno, std::generic_category(), file.string());
}

void replaceFileAtomically(const fs::path& target,
                           const std::function<void(const fs::path& temp)>& write) {
    // A device or a pipe (/dev/null, /dev/full, a FIFO, or a link to one) is
    // not a file to replace: renaming over it would replace the device node
    // itself, which root may do. Write into it, and let its errors (a full
    // disk) come back from the write.
    std::error_code noStatus;
    const fs::file_status status = fs::status(target, noStatus);
    if (!noStatus && fs::exists(status) && !fs::is_regular_file(status) &&
        !fs::is_directory(status)) {
        write(target);
        return;
    }
    const fs::path temp = temporaryBeside(target);
    try {
        write(temp);
        flushToDisk(temp);
        fs::rename(temp, target);
    } catch (...) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw;
    }
}

void replaceFileWithText(const fs::path& target, std::string_view text) {
    try {
        replaceFileAtomically(target, [&](const fs::path& temp) { writeAllBytes(temp, text); });
    } catch (const std::system_error& e) {
        throw std::system_error(e.code(), target.string());
    }
}

}  // namespace whitted
