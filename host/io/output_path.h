#pragma once
// Output files: checked before any work is done (a bad -o fails fast, naming the path and the reason),
// never one of the command's inputs, and written atomically (a temporary file beside the target, renamed
// into place), so that a failure or a signal never leaves a partial file.
//
// What an output path may already hold:
// - nothing: the file is created;
// - a writable regular file: it is replaced, atomically;
// - a read-only regular file (no write permission bit): refused, the file is left alone;
// - a symbolic link: followed, so the file it points to is written and the link stays a link;
// - a directory, device, FIFO or socket: refused.
#include <string>
#include <vector>

namespace tf {

// Checks `path` as above, and that it ends in one of `extensions` (case-insensitive, e.g. ".png"), that
// its directory exists and is writable, and that it is not the same file as any of `inputs` (same device
// and inode, so another name or a link to an input is caught too). Returns the path to write: `path`
// itself, or the end of its chain of symbolic links. Throws tf::Error naming the path and the reason.
std::string checked_output_path(const std::string& path, const std::vector<std::string>& extensions,
                                const std::vector<std::string>& inputs = {});

// Throws tf::Error unless files can be created in `directory` (exists, is a directory, is writable).
// `what` names the output in the message ("bench --out results").
void check_writable_directory(const std::string& directory, const std::string& what);

// Beside the target, unique per process (NAME.tmp-PID, the name shortened to stay within the file system's
// name limit): written first, renamed into place when complete. The name is registered with the signal
// cleanup (temporary_files.h), so SIGINT/SIGTERM/SIGHUP remove it.
std::string temporary_path_for(const std::string& path);

// Writes text to path via a temporary file and a rename, so a failure leaves no partial file.
void write_file_atomic(const std::string& path, const std::string& content);

} // namespace tf
