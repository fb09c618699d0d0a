#include "runtime/bounded_file.h"

#include <sys/stat.h>

#include <cstdint>
#include <fstream>

namespace ws {
namespace {

[[noreturn]] void TooLarge(uint64_t bytes, size_t max_bytes, bool at_least) {
  throw BoundedFileError((at_least ? "more than " : std::to_string(bytes) + " bytes: more than ") +
                         std::to_string(max_bytes) + " bytes, larger than such a file can be");
}

}  // namespace

void RequireBoundedFile(const std::string& path, size_t max_bytes) {
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) throw BoundedFileError("cannot open the file");
  if (!S_ISREG(info.st_mode)) throw BoundedFileError("not a regular file (a folder, a FIFO or a device)");
  if (uint64_t(info.st_size) > max_bytes) TooLarge(uint64_t(info.st_size), max_bytes, false);
}

std::string ReadBoundedFile(const std::string& path, size_t max_bytes) {
  RequireBoundedFile(path, max_bytes);
  std::ifstream file(path, std::ios::binary);
  if (!file) throw BoundedFileError("cannot open the file");
  std::string text;
  char chunk[1 << 16];
  while (file.read(chunk, sizeof chunk) || file.gcount() > 0) {
    text.append(chunk, size_t(file.gcount()));
    if (text.size() > max_bytes) TooLarge(text.size(), max_bytes, true);
  }
  if (file.bad()) throw BoundedFileError("cannot read the file");
  return text;
}

}  // namespace ws
