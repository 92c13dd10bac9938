#pragma once
// Output files: checked before any work is done (a bad -o fails fast, naming the path and the reason),
// never one of the command's inputs, and written atomically (a temporary file beside the target, renamed
// into place), so that a failure or a signal never leaves a partial file. The check creates that temporary
// (io/temporary_files.h: exclusively, under a random name), so "can this be written" is answered by the
// file system itself before the work, not guessed from permission bits.
//
// What an output path may already hold:
// - nothing: the file is created;
// - a writable regular file: it is replaced, atomically;
// - a read-only regular file (no write permission bit): refused, the file is left alone;
// - a symbolic link: followed, so the file it points to is written and the link stays a link;
// - a directory, device, FIFO or socket: refused.
#include <functional>
#include <string>
#include <vector>

namespace tf {

// Checks `path` as above, and that it ends in one of `extensions` (case-insensitive, e.g. ".png"), that
// its directory exists and is writable, and that it is not the same file as any of `inputs` (same device
// and inode, so another name or a link to an input is caught too). Returns the path to write: `path`
// itself, or the end of its chain of symbolic links. Creates the output's temporary file beside it, which
// write_output later fills and renames (or the process removes on exit). Throws tf::Error naming the path
// and the reason.
std::string checked_output_path(const std::string& path, const std::vector<std::string>& extensions,
                                const std::vector<std::string>& inputs = {});

// The path a chain of symbolic links ends at (`path` itself when it is none; it need not exist).
// Throws tf::Error for a loop or an unreadable link.
std::string end_of_links(const std::string& path);

// The same checks, leaving nothing behind (a temporary is created and removed at once, so the directory's
// answer is still the file system's): for outputs checked long before they are written (a viewer script's
// screenshots, checked before its window opens; write_output makes the temporary when the file is written).
std::string check_output_path(const std::string& path, const std::vector<std::string>& extensions,
                              const std::vector<std::string>& inputs = {});

// Throws tf::Error, naming `shown`, if the last part of `path` is longer than its directory allows: the
// finished output (renamed there at the end) could not take its place.
void check_name_fits(const std::string& path, const std::string& shown);

// Throws tf::Error unless files can be created in `directory` (exists, is a directory, is writable).
// `what` names the output in the message ("bench --out results").
void check_writable_directory(const std::string& directory, const std::string& what);

// Writes the output at `path` through its temporary file (the one checked_output_path created, or a new
// one), then renames it into place: `write` gets the temporary's open descriptor. On any failure the
// temporary is removed and nothing at `path` changes.
void write_output(const std::string& path, const std::function<void(int fd)>& write);

// Writes text to path the same way.
void write_file_atomic(const std::string& path, const std::string& content);

// Writes all of `size` bytes to fd, or throws tf::Error naming `path` (disk full, ...).
void write_all(int fd, const void* bytes, size_t size, const std::string& path);

} // namespace tf
