#pragma once
// The files a screenshot writes: PATH.png, and for the scene alone PATH.txt (the render lines) and PATH.json
// (the state). A screenshot never replaces a file it did not create: where any of them exists and this
// viewer did not write it (earlier in the same run), the screenshot is refused, naming the file. A script's
// screenshots are checked so before the window opens; the panel and F12 pick a free name instead
// (unused_screenshot_path).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tf {

// A file as it was when written: one put in its place since (even on a reused inode) differs in one of these.
struct FileIdentity {
    uint64_t device = 0, inode = 0;
    int64_t changed_ns = 0; // st_ctim
    bool operator==(const FileIdentity&) const = default;
};

// What this viewer has written, by path.
struct WrittenFiles {
    std::map<std::string, FileIdentity> identity;
};

// The screenshot's files for `path` (PATH.png; and .txt and .json unless with_ui), each checked as an output
// that is none of `inputs` (check_output_path: nothing is created until the files are written) and that does not exist unless it is in `written`. Returns
// the .png's path to write. Throws tf::Error naming the file.
std::string checked_screenshot_paths(const std::string& path, bool with_ui, const std::vector<std::string>& inputs,
                                     const WrittenFiles& written = {});
// The .txt and .json written beside a scene screenshot PATH.png.
std::string screenshot_side_file(const std::string& png_path, const std::string& extension);
// Records a file just written (its identity now), so that a later screenshot may replace it.
void remember_written(WrittenFiles& written, const std::string& path);
// `wanted`, or with -1, -2, ... before .png where it or its .txt/.json exists already.
std::string unused_screenshot_path(const std::string& wanted);

} // namespace tf
