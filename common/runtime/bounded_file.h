// A file read whole, checked first: `stat` says it is a regular file of at
// most max_bytes before a byte is read, so a FIFO never blocks the read, a
// device (/dev/zero) never makes it endless, and a file too large for what
// it claims to be is refused at the cost of a stat (docs/reliability.md,
// "Bounded inputs"). The size is checked again while reading: a file that
// grows meanwhile is refused too.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace ws {

// The reason alone ("not a regular file (a folder, a FIFO or a device)",
// "70000000 bytes: more than 67108864 bytes"); the caller names the file.
class BoundedFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws BoundedFileError unless `path` is a regular file of at most max_bytes.
void RequireBoundedFile(const std::string& path, size_t max_bytes);

// RequireBoundedFile, then the whole file.
std::string ReadBoundedFile(const std::string& path, size_t max_bytes);

}  // namespace ws
