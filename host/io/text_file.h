#pragma once
// Text inputs (the viewer's script and state, the golden manifest, the sample command's lookups): read
// whole, from a regular file only, up to a cap. A device (/dev/zero), a FIFO or a socket may never end or
// never answer, so they are refused before a byte is read, and a file over its cap is refused from its size:
// no input makes a reader block or grow without bound.
#include <cstdint>
#include <string>

namespace tf {

// The contents of `path` (a symbolic link is followed). Throws tf::Error naming `path` and `what` (as a
// message says it: "the script") when the file cannot be opened (with the system's reason: "Permission
// denied"), is not a regular file (saying what it is: a directory, a character device, a FIFO, ...), or
// holds more than max_bytes. Never blocks on a FIFO: it is refused without waiting for a writer.
std::string read_text_file(const std::string& path, uint64_t max_bytes, const std::string& what);

// Throws tf::Error naming `path` and `what` ("an image file") when it exists and is a device, a FIFO or a
// socket (a symbolic link is followed), without opening it: for readers that open files by name (the image
// library), which would wait on a FIFO for ever or read a device without end. A missing path or a directory
// is left to the reader's own message.
void refuse_special_file(const std::string& path, const std::string& what);

} // namespace tf
