#pragma once
// A results directory a command may reuse (golden's --out): created by the command, or marked as its own by
// an earlier run, with the list of files it wrote there. Nothing else in it is ever removed or replaced.
#include <string>
#include <vector>

namespace tf {

struct OwnedDirectory {
    std::string path;
    std::string marker;              // path/.texfilter-COMMAND: says whose it is and lists the files
    std::string command;
    std::vector<std::string> files;  // relative to path, written by this run
};

// Before any work: creates `path` (its parent must exist and be writable), or takes an existing empty
// directory, or one that an earlier run of `command` marked, removing the files that run listed (an old
// failure image would mislead). Refuses anything else, naming the path and why. The marker is written at once.
// The directory stays locked (flock) until the process ends: a second run into it is refused. A symbolic
// link to a directory is followed.
OwnedDirectory claim_directory(const std::string& path, const std::string& command);

// A results directory written whole or not at all (bench --out, build --out): `out` must be new or an empty
// directory whose parent is writable (check_new_directory, before any work; a link to one is followed);
// the files go to a private staging directory beside it (io/temporary_files.h: created exclusively under a
// random name), which publish() renames into place. A staging directory not published is removed (an
// error, a signal, an exit).
void check_new_directory(const std::string& out, const std::string& what);
struct StagingDirectory {
    std::string path;   // beside the target: NAME.tmp-XXXXXX
    std::string target;
    bool published = false;
    explicit StagingDirectory(const std::string& target); // creates it
    ~StagingDirectory();
    void publish(); // the target (empty, checked before) is replaced by the staging directory
    StagingDirectory(const StagingDirectory&) = delete;
    StagingDirectory& operator=(const StagingDirectory&) = delete;
};

// Lists a file before it is written (relative to the directory, no "..": sub/NAME), so that even an
// interrupted run leaves a marker that covers everything it wrote. Rewrites the marker atomically.
void record_file(OwnedDirectory& directory, const std::string& relative);

} // namespace tf
