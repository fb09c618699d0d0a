#include "runtime/output_folder.h"

#include <unistd.h>

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

void RequireWritableFolderOf(const std::string& option, const std::string& path) {
  if (path.empty()) return;
  std::string folder = std::filesystem::path(path).parent_path().string();
  if (folder.empty()) folder = ".";
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw std::invalid_argument(option + " " + path + ": the folder " + folder + " does not exist");
  if (access(folder.c_str(), W_OK) != 0)
    throw std::invalid_argument(option + " " + path + ": the folder " + folder +
                                " is not writable by this process");
}

}  // namespace ws
