#include "fuzz_support.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace ws::fuzz {

std::string WriteInputFile(const uint8_t* data, size_t size, const std::string& extension) {
  static const std::string path = (std::filesystem::temp_directory_path() /
                                   ("ws-fuzz-" + std::to_string(getpid()) + extension))
                                      .string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  if (!out) Violated("cannot write the input file " + path);
  return path;
}

}  // namespace ws::fuzz
