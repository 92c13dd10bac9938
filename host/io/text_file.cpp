#include "io/text_file.h"
#include "core/memory_budget.h"
#include "texture/error.h"
#include <algorithm>
#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace tf {

namespace {

const char* kind_of(mode_t mode)
{
    return S_ISDIR(mode)    ? "a directory"
           : S_ISCHR(mode)  ? "a character device"
           : S_ISBLK(mode)  ? "a block device"
           : S_ISFIFO(mode) ? "a pipe (FIFO)"
           : S_ISSOCK(mode) ? "a socket"
                            : "an unknown kind of file";
}

void require_regular(const std::string& path, mode_t mode, const std::string& what)
{
    if (!S_ISREG(mode))
        throw Error(path + ": is " + kind_of(mode) + ", not a regular file (" + what + " must be one)");
}

std::string reason(int error) { return std::generic_category().message(error); }

std::string bytes_text(uint64_t bytes) { return format_bytes(bytes) + " (" + std::to_string(bytes) + " bytes)"; }

struct FileDescriptor {
    int fd = -1;
    ~FileDescriptor()
    {
        if (fd >= 0)
            ::close(fd);
    }
};

} // namespace

void refuse_special_file(const std::string& path, const std::string& what)
{
    struct stat status {};
    if (::stat(path.c_str(), &status) == 0 && !S_ISDIR(status.st_mode))
        require_regular(path, status.st_mode, what);
}

std::string read_text_file(const std::string& path, uint64_t max_bytes, const std::string& what)
{
    // The path's kind first, so that a device or a FIFO is never opened (opening a device can do things).
    struct stat status {};
    if (::stat(path.c_str(), &status) == 0)
        require_regular(path, status.st_mode, what);
    // Then the file opened, checked itself in case the path changed in between; O_NONBLOCK opens a FIFO put
    // there since without waiting for a writer, so that it is refused rather than waited on.
    FileDescriptor file;
    file.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (file.fd < 0) {
        const int error = errno;
        throw Error(path + ": cannot open " + what + " (" + reason(error) + ")");
    }
    if (::fstat(file.fd, &status) != 0) {
        const int error = errno;
        throw Error(path + ": cannot read " + what + " (" + reason(error) + ")");
    }
    require_regular(path, status.st_mode, what);
    const uint64_t size = uint64_t(status.st_size);
    if (size > max_bytes)
        throw Error(path + ": " + what + " is " + bytes_text(size) + ", over its cap of " + bytes_text(max_bytes));
    std::string text;
    text.reserve(size_t(size));
    // At most max_bytes + 1 bytes: a file that grows while it is read is refused, not followed.
    char buffer[1 << 16];
    while (text.size() <= max_bytes) {
        const size_t want = size_t(std::min<uint64_t>(sizeof buffer, max_bytes + 1 - text.size()));
        const ssize_t got = ::read(file.fd, buffer, want);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            const int error = errno;
            throw Error(path + ": cannot read " + what + " (" + reason(error) + ")");
        }
        if (got == 0)
            break;
        text.append(buffer, size_t(got));
    }
    if (text.size() > max_bytes)
        throw Error(path + ": " + what + " grew past its cap of " + bytes_text(max_bytes) + " while it was read");
    return text;
}

} // namespace tf
