#include "io/output_path.h"
#include "texture/error.h"
#include "io/temporary_files.h"
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <sys/stat.h>
#include <unistd.h>

namespace tf {

namespace {

namespace fs = std::filesystem;

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string errno_text(int error) { return std::strerror(error); }

bool same_file(const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; }

// Follows a chain of symbolic links to the path that will really be written (which need not exist yet).
fs::path follow_links(const std::string& path)
{
    fs::path p(path);
    for (int hops = 0;; ++hops) {
        struct stat link_status {};
        if (lstat(p.c_str(), &link_status) != 0 || !S_ISLNK(link_status.st_mode))
            return p;
        if (hops == 40) // the kernel's own limit (ELOOP)
            throw Error(path + ": too many levels of symbolic links");
        std::error_code ec;
        fs::path target = fs::read_symlink(p, ec);
        if (ec)
            throw Error(path + ": cannot read the symbolic link (" + ec.message() + ")");
        p = target.is_absolute() ? target : p.parent_path() / target;
    }
}

// The first ancestor of `directory` that exists but is not a directory ("a/file.png" for a/file.png/x),
// or "" when there is none (then a part is simply missing).
std::string file_in_the_way(const fs::path& directory)
{
    for (fs::path p = directory; !p.empty() && p != p.root_path(); p = p.parent_path()) {
        struct stat status {};
        if (stat(p.c_str(), &status) == 0)
            return S_ISDIR(status.st_mode) ? "" : p.string();
    }
    return "";
}

// Temporaries made by checked_output_path, by the target they will become, until write_output uses them.
std::mutex reservations_mutex;
std::map<std::string, TemporaryFile>& reservations()
{
    static std::map<std::string, TemporaryFile> files;
    return files;
}

void reserve_temporary(const std::string& target)
{
    std::lock_guard<std::mutex> lock(reservations_mutex);
    if (reservations().count(target) == 0)
        reservations()[target] = create_temporary_file(target);
}

TemporaryFile take_temporary(const std::string& target)
{
    {
        std::lock_guard<std::mutex> lock(reservations_mutex);
        auto it = reservations().find(target);
        if (it != reservations().end()) {
            TemporaryFile file = it->second;
            reservations().erase(it);
            return file;
        }
    }
    return create_temporary_file(target);
}

} // namespace

std::string end_of_links(const std::string& path) { return follow_links(path).string(); }

void check_name_fits(const std::string& path, const std::string& shown)
{
    const fs::path target(path);
    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    const long limit = pathconf(parent.c_str(), _PC_NAME_MAX);
    const size_t name_max = size_t(limit > 0 ? limit : NAME_MAX);
    const size_t name_size = target.filename().string().size();
    if (name_size > name_max)
        throw Error(shown.substr(0, 80) + "...: the name is " + std::to_string(name_size) + " bytes, longer than " +
                    std::to_string(name_max) + ", the most " + parent.string() + " allows");
}

namespace {
// The checks of checked_output_path, before anything is created; returns the path to write.
std::string output_target(const std::string& path, const std::vector<std::string>& extensions,
                          const std::vector<std::string>& inputs);
} // namespace

void check_writable_directory(const std::string& directory, const std::string& what)
{
    struct stat status {};
    if (stat(directory.c_str(), &status) != 0)
        throw Error(what + ": the directory " + directory + " does not exist (" + errno_text(errno) + ")");
    if (!S_ISDIR(status.st_mode))
        throw Error(what + ": " + directory + " is not a directory");
    if (access(directory.c_str(), W_OK | X_OK) != 0)
        throw Error(what + ": cannot create files in " + directory + " (" + errno_text(errno) + ")");
}

std::string checked_output_path(const std::string& path, const std::vector<std::string>& extensions,
                                const std::vector<std::string>& inputs)
{
    const std::string target = output_target(path, extensions, inputs);
    // Last, once everything else holds: creating the temporary is the real test that the directory takes
    // files (access() says yes to root in /proc; a read-only mount says no only here).
    reserve_temporary(target);
    return target;
}

std::string check_output_path(const std::string& path, const std::vector<std::string>& extensions,
                              const std::vector<std::string>& inputs)
{
    const std::string target = output_target(path, extensions, inputs);
    remove_temporary(create_temporary_file(target).path); // the same real test, leaving nothing behind
    return target;
}

namespace {

std::string output_target(const std::string& path, const std::vector<std::string>& extensions,
                          const std::vector<std::string>& inputs)
{
    if (path.empty())
        throw Error("the output path is empty");
    const fs::path target = follow_links(path);
    const std::string shown = target.string() == path ? path : path + " (a link to " + target.string() + ")";

    struct stat existing {};
    const bool exists = stat(target.c_str(), &existing) == 0;
    if (exists) {
        if (S_ISDIR(existing.st_mode))
            throw Error(shown + ": is a directory, not an output file");
        if (!S_ISREG(existing.st_mode))
            throw Error(shown + ": is not a regular file (a device, FIFO or socket); not replaced");
        // The permission bits, not access(): root may write anything, but a read-only file says "keep me".
        if ((existing.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 || access(target.c_str(), W_OK) != 0)
            throw Error(shown + ": is read-only; not replaced (make it writable or choose another output)");
    }

    std::string ext = lower(target.extension().string());
    if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
        std::string list;
        for (const std::string& e : extensions)
            list += (list.empty() ? "" : ", ") + e;
        throw Error(shown + ": unsupported output format " + (ext.empty() ? "(no extension)" : "'" + ext + "'") +
                    " (use " + list + ")");
    }

    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    struct stat parent_status {};
    if (stat(parent.c_str(), &parent_status) != 0 || !S_ISDIR(parent_status.st_mode)) {
        if (const std::string file = file_in_the_way(parent); !file.empty())
            throw Error(shown + ": " + file + " is a file, not a directory");
        throw Error(shown + ": the output directory " + parent.string() + " does not exist");
    }
    check_name_fits(target.string(), shown);
    // The rename that puts the output in place replaces a file in a sticky directory (/tmp) only for the file's
    // or the directory's owner (or root): anyone else would find out only after the work.
    const uid_t user = geteuid();
    if (exists && (parent_status.st_mode & S_ISVTX) && user != 0 && existing.st_uid != user &&
        parent_status.st_uid != user)
        throw Error(shown + ": belongs to another user in the sticky directory " + parent.string() +
                    ", where only its owner may replace it (choose another output)");

    if (exists)
        for (const std::string& input : inputs) {
            struct stat input_status {};
            if (stat(input.c_str(), &input_status) == 0 && same_file(input_status, existing))
                throw Error(shown + ": is the input " + input + "; writing it would destroy the input "
                                    "(choose another output)");
        }
    return target.string();
}

} // namespace

void write_all(int fd, const void* bytes, size_t size, const std::string& path)
{
    const char* p = static_cast<const char*>(bytes);
    while (size > 0) {
        const ssize_t n = ::write(fd, p, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            throw Error(path + ": cannot write the file (" + errno_text(n < 0 ? errno : ENOSPC) + ")");
        p += n;
        size -= size_t(n);
    }
}

void write_output(const std::string& path, const std::function<void(int fd)>& write)
{
    const std::string target = follow_links(path).string();
    const TemporaryFile temporary = take_temporary(target);
    try {
        const int fd = open_temporary_file(temporary, path);
        try {
            write(fd);
        } catch (...) {
            close(fd);
            throw;
        }
        if (close(fd) != 0)
            throw Error(path + ": cannot write the file (" + errno_text(errno) + ")");
        // rename() replaces whatever is at the target, a link included, never what a link points to.
        if (rename(temporary.path.c_str(), target.c_str()) != 0) {
            const int error = errno;
            throw Error(path + ": cannot move the finished file into place (" + errno_text(error) + ")");
        }
    } catch (...) {
        remove_temporary(temporary.path);
        throw;
    }
    release_temporary(temporary.path);
}

void write_file_atomic(const std::string& path, const std::string& content)
{
    write_output(path, [&](int fd) { write_all(fd, content.data(), content.size(), path); });
}

} // namespace tf
