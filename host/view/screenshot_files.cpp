#include "view/screenshot_files.h"
#include "io/output_path.h"
#include "texture/error.h"
#include <optional>
#include <sys/stat.h>

namespace tf {

namespace {

std::string stem_of(const std::string& path) { return path.substr(0, path.size() - 4); } // checked: ends in .png

// What is at `path`, a symbolic link itself rather than what it points to; none where nothing is (or it
// cannot be seen: writing it then fails with the reason).
std::optional<FileIdentity> identity_of(const std::string& path)
{
    struct stat status {};
    if (::lstat(path.c_str(), &status) != 0)
        return std::nullopt;
    return FileIdentity{uint64_t(status.st_dev), uint64_t(status.st_ino),
                        int64_t(status.st_ctim.tv_sec) * 1000000000 + int64_t(status.st_ctim.tv_nsec)};
}

void refuse_unless_written_here(const std::string& file, const WrittenFiles& written)
{
    const auto identity = identity_of(file);
    if (!identity)
        return;
    const auto it = written.identity.find(file);
    if (it != written.identity.end() && it->second == *identity)
        return;
    throw Error(file + ": exists, and this viewer did not write it: a screenshot replaces no file it did not "
                       "create (remove it, or choose another name)");
}

} // namespace

std::string screenshot_side_file(const std::string& png_path, const std::string& extension)
{
    return stem_of(png_path) + extension;
}

std::string checked_screenshot_paths(const std::string& requested, bool with_ui, const std::vector<std::string>& inputs,
                                     const WrittenFiles& written)
{
    const std::string path = check_output_path(requested, {".png"}, inputs);
    std::vector<std::string> files = {requested};
    if (!with_ui) // the files beside it
        for (const char* extension : {".txt", ".json"}) {
            files.push_back(screenshot_side_file(path, extension));
            check_output_path(files.back(), {extension}, inputs);
        }
    for (const std::string& file : files)
        refuse_unless_written_here(file, written);
    return path;
}

void remember_written(WrittenFiles& written, const std::string& path)
{
    if (const auto identity = identity_of(path))
        written.identity[path] = *identity;
}

std::string unused_screenshot_path(const std::string& wanted)
{
    const std::string stem = wanted.size() > 4 && wanted.substr(wanted.size() - 4) == ".png" ? stem_of(wanted) : wanted;
    for (int n = 0; n < 10000; ++n) { // bounded: past that, checked_screenshot_paths says what is wrong
        const std::string s = n ? stem + "-" + std::to_string(n) : stem;
        if (!identity_of(s + ".png") && !identity_of(s + ".txt") && !identity_of(s + ".json"))
            return s + ".png";
    }
    return wanted;
}

} // namespace tf
