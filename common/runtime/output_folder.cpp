#include "runtime/output_folder.h"

#include <filesystem>
#include <stdexcept>

namespace ws {

std::string FileInFolder(const std::string& folder, const std::string& name) {
  if (folder.empty()) throw std::invalid_argument("this process was started without a folder for such files");
  if (name.empty() || name.find('/') != std::string::npos || name.find("..") != std::string::npos)
    throw std::invalid_argument("'" + name + "' is not a plain file name (no '/', no '..'); files go only into " +
                                folder);
  return (std::filesystem::path(folder) / name).string();
}

}  // namespace ws
