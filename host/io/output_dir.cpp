#include "io/output_dir.h"
#include "texture/error.h"
#include "io/output_path.h"
#include "io/temporary_files.h"
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace tf {

namespace {

namespace fs = std::filesystem;

std::string heading(const std::string& command)
{
    return "# texfilter " + command + " output directory. texfilter " + command +
           " removes the files listed here (and only these) when it runs again with this --out.";
}

// Only plain relative names below the directory: a tampered marker must not reach outside it.
bool safe_relative(const std::string& relative)
{
    if (relative.empty() || relative.front() == '/')
        return false;
    for (const fs::path& part : fs::path(relative))
        if (part == ".." || part == ".")
            return false;
    return true;
}

// The first symbolic link anywhere below root (not followed), or "": a run writes its files into root's
// folders and removes the files an earlier run listed, and a link there, which texfilter never makes, would
// send either anywhere.
std::string link_below(const std::string& root)
{
    std::error_code ec;
    for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_symlink(ec))
            return it->path().string();
    return "";
}

void write_marker(const OwnedDirectory& directory)
{
    std::string text = heading(directory.command) + "\n";
    for (const std::string& f : directory.files)
        text += f + "\n";
    write_file_atomic(directory.marker, text);
}

// The files an earlier run listed; throws, before anything is removed, if the marker is not ours or lists a
// path that leaves its directory.
std::vector<std::string> read_marker(const std::string& marker, const std::string& command)
{
    std::ifstream in(marker);
    std::string line;
    if (!in || !std::getline(in, line) || line != heading(command))
        throw Error(marker + ": is not a texfilter " + command + " marker; nothing in its directory was touched");
    std::vector<std::string> files;
    while (std::getline(in, line))
        if (!line.empty()) {
            if (!safe_relative(line))
                throw Error(marker + ": lists '" + line.substr(0, 60) +
                            "', which is not a file below its directory; nothing was touched");
            files.push_back(line);
        }
    return files;
}

void remove_listed(const std::string& root, const std::vector<std::string>& files)
{
    for (const std::string& f : files) {
        fs::path p = fs::path(root) / f;
        std::error_code ec;
        if (fs::is_regular_file(fs::symlink_status(p, ec)))
            fs::remove(p, ec);
        // The folders the files were in go too, once empty (fs::remove leaves a non-empty one alone).
        for (fs::path dir = fs::path(f).parent_path(); !dir.empty(); dir = dir.parent_path())
            if (fs::is_directory(fs::symlink_status(fs::path(root) / dir, ec))) // a link is never removed
                fs::remove(fs::path(root) / dir, ec);
    }
}

// Held until the process ends (the descriptor is never closed): a second run with the same --out, even in
// another process, is refused instead of mixing its markers, reports and failure images with this one's.
void lock_for_this_run(const std::string& path, const std::string& what)
{
    const int fd = open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        throw Error(what + ": cannot open the directory (" + std::strerror(errno) + ")");
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        close(fd);
        if (error == EWOULDBLOCK)
            throw Error(what + ": another texfilter run is writing into this directory now; nothing was touched "
                        "(wait for it, or choose another directory)");
        throw Error(what + ": cannot lock the directory (" + std::strerror(error) + ")");
    }
}

// Permissions of a directory made private while it was filled: what mkdir would have given it.
void make_public(const std::string& path)
{
    const mode_t mask = umask(0);
    umask(mask);
    chmod(path.c_str(), 0777 & ~mask);
}

} // namespace

OwnedDirectory claim_directory(const std::string& path, const std::string& command)
{
    if (path.empty())
        throw Error(command + " --out: the directory path is empty");
    const std::string what = command + " --out " + path;
    OwnedDirectory directory;
    directory.path = end_of_links(path); // a link to a directory is followed, as -o follows a link to a file
    directory.command = command;
    directory.marker = (fs::path(directory.path) / (".texfilter-" + command)).string();
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(directory.path, ec);
    if (!fs::exists(status)) {
        fs::path parent = fs::path(directory.path).parent_path();
        check_writable_directory(parent.empty() ? "." : parent.string(), what);
        if (mkdir(directory.path.c_str(), 0777) != 0) // fails if anything took the name meanwhile
            throw Error(what + ": cannot create the directory (" + std::strerror(errno) + ")");
        lock_for_this_run(directory.path, what);
    } else if (!fs::is_directory(status)) {
        throw Error(what + ": exists and is not a directory");
    } else if (lock_for_this_run(directory.path, what); fs::exists(fs::symlink_status(directory.marker, ec))) {
        check_writable_directory(directory.path, what);
        const std::vector<std::string> listed = read_marker(directory.marker, command);
        if (const std::string link = link_below(directory.path); !link.empty()) // a listed file through one included
            throw Error(what + ": " + link + " is a symbolic link, which texfilter never makes (a run would write "
                        "through it); nothing was touched: remove it or choose a new directory");
        remove_listed(directory.path, listed);
    } else if (!fs::is_empty(directory.path, ec) || ec) {
        throw Error(what + ": exists, is not empty and was not made by texfilter " + command +
                    " (no " + fs::path(directory.marker).filename().string() +
                    " in it); nothing was touched: choose a new directory");
    } else {
        check_writable_directory(directory.path, what);
    }
    write_marker(directory);
    return directory;
}

void record_file(OwnedDirectory& directory, const std::string& relative)
{
    if (!safe_relative(relative))
        throw Error("internal: '" + relative + "' is not a plain name below " + directory.path);
    for (const std::string& f : directory.files)
        if (f == relative)
            return;
    directory.files.push_back(relative);
    write_marker(directory);
}

void check_new_directory(const std::string& out, const std::string& what)
{
    if (out.empty())
        throw Error(what + ": the directory path is empty");
    const fs::path path = end_of_links(out); // a link to a directory is followed, as -o follows a link to a file
    const std::string shown = path.string() == out ? out : out + " (a link to " + path.string() + ")";
    const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(parent, ec))
        throw Error(shown + ": its parent directory does not exist");
    check_writable_directory(parent.string(), what + " " + shown);
    check_name_fits(path.string(), what + " " + shown);
    const fs::file_status status = fs::symlink_status(path, ec);
    if (fs::exists(status) && !fs::is_directory(status))
        throw Error(shown + ": exists and is not a directory (" + what + " never overwrites results)");
    if (fs::exists(status) && !fs::is_empty(path, ec))
        throw Error(shown + ": is not an empty directory (" + what + " never overwrites results)");
}

StagingDirectory::StagingDirectory(const std::string& target_path)
    : path(create_temporary_directory(end_of_links(target_path))), target(end_of_links(target_path))
{
}

StagingDirectory::~StagingDirectory()
{
    if (!published)
        remove_temporary(path);
}

void StagingDirectory::publish()
{
    make_public(path);
    // rename() takes the target's place only if it is missing or an empty directory (checked before the work);
    // anything put there since is kept, and this fails.
    if (rename(path.c_str(), target.c_str()) != 0)
        throw Error(target + ": cannot move the finished results into place (" + std::strerror(errno) + ")");
    release_temporary(path);
    published = true;
}

} // namespace tf
