#pragma once
// Temporaries (the files and staging directories outputs are written through) are this process's alone:
// - created exclusively (O_CREAT|O_EXCL, which never follows a link) under an unpredictable name beside
//   their target (NAME.tmp-XXXXXX, X random), so nothing someone else left or planted there is ever
//   written, adopted or removed;
// - removed, and only they, when the process ends without having moved them into place: on an exception
//   or a normal exit (atexit) and on SIGINT, SIGTERM or SIGHUP (one thread waits for those signals,
//   removes the temporaries, then lets the signal end the process as it would have: exit status 128 + N).
#include <string>
#include <sys/types.h>

namespace tf {

// Call first in main(), before any other thread exists.
void install_signal_cleanup();

struct TemporaryFile {
    std::string path; // DIR/NAME.tmp-XXXXXX
    dev_t device = 0; // what was created, so a later open can prove it reached the same file
    ino_t inode = 0;
};

// Creates an empty file (mode 0666 less the umask) beside `target` and registers it for removal.
// Throws tf::Error naming `target` and the system's reason (Permission denied, Read-only file system, ...):
// creating the temporary is the check that the output can be written at all.
TemporaryFile create_temporary_file(const std::string& target);

// Opens a temporary this process created for writing (truncated), refusing a link or any other file that
// has taken its name since. Returns the descriptor; throws tf::Error naming `target`.
int open_temporary_file(const TemporaryFile& file, const std::string& target);

// Creates a private directory (mode 0700: no one else can put anything in it) beside `target` and
// registers it; removing it on exit removes everything in it, all of which this process wrote.
std::string create_temporary_directory(const std::string& target);

// The temporary was renamed into place (or removed by the caller): nothing is left to remove.
void release_temporary(const std::string& path);

// Removes a temporary now (file, or directory with its contents) and releases it.
void remove_temporary(const std::string& path);

} // namespace tf
