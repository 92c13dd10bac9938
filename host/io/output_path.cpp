#include "io/output_path.h"
#include "texture/error.h"
#include "io/temporary_files.h"
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
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

bool same_file(const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; }

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
    if (stat(parent.c_str(), &parent_status) != 0 || !S_ISDIR(parent_status.st_mode))
        throw Error(shown + ": the output directory " + parent.string() + " does not exist");
    if (access(parent.c_str(), W_OK | X_OK) != 0)
        throw Error(shown + ": cannot create files in " + parent.string() + " (" + errno_text(errno) + ")");
    // The name itself must fit the file system, or the finished file could not be moved into place.
    const long name_max = pathconf(parent.c_str(), _PC_NAME_MAX);
    const size_t name_size = target.filename().string().size();
    if (name_size > size_t(name_max > 0 ? name_max : NAME_MAX))
        throw Error(shown.substr(0, 80) + "...: the file name is " + std::to_string(name_size) + " bytes, longer than " +
                    std::to_string(name_max > 0 ? name_max : NAME_MAX) + ", the most " + parent.string() + " allows");

    if (exists)
        for (const std::string& input : inputs) {
            struct stat input_status {};
            if (stat(input.c_str(), &input_status) == 0 && same_file(input_status, existing))
                throw Error(shown + ": is the input " + input + "; writing it would destroy the input "
                                    "(choose another output)");
        }
    return target.string();
}

std::string temporary_path_for(const std::string& path)
{
    const fs::path p(path);
    const fs::path directory = p.parent_path();
    const std::string suffix = ".tmp-" + std::to_string(getpid());
    long name_max = pathconf(directory.empty() ? "." : directory.c_str(), _PC_NAME_MAX);
    if (name_max <= 0)
        name_max = NAME_MAX;
    std::string name = p.filename().string();
    if (name.size() + suffix.size() > size_t(name_max))
        name.resize(size_t(name_max) - std::min(size_t(name_max), suffix.size()));
    const std::string temporary = (directory / (name + suffix)).string();
    register_temporary(temporary);
    return temporary;
}

void write_file_atomic(const std::string& path, const std::string& content)
{
    std::string temp = temporary_path_for(path);
    {
        std::ofstream out(temp, std::ios::binary);
        const int open_error = errno;
        if (!out)
            throw Error(path + ": cannot write the file (" + errno_text(open_error) + ")");
        out << content;
        out.close();
        if (!out) {
            std::remove(temp.c_str());
            throw Error(path + ": cannot write the file (disk full?)");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::remove(temp.c_str());
        throw Error(path + ": cannot write the file (" + ec.message() + ")");
    }
}

} // namespace tf
