#pragma once
// Temporary outputs (NAME.tmp-PID files and directories) must not outlive an interrupted command.
// install_signal_cleanup() blocks SIGINT, SIGTERM and SIGHUP in the calling thread (and so in every
// thread started after it) and hands them to one thread that removes every registered temporary and
// then lets the signal end the process as it would have (exit status 128 + signal).
#include <string>

namespace tf {

// Call first in main(), before any other thread exists.
void install_signal_cleanup();

// Remembers a temporary path for removal on a signal (a file, or a directory removed with its contents).
// Paths that no longer exist when the signal comes (renamed into place, or removed) are simply skipped:
// the names are unique to this process, so nothing else can have taken them.
void register_temporary(const std::string& path);

} // namespace tf
