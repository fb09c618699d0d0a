#include "runtime/output_folder.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>
#include <stdexcept>

#include "runtime/atomic_file.h"

namespace ws {
namespace {

constexpr size_t kMaxNameBytes = 200;

}  // namespace

std::string CommandOutputFile(const CommandOutput& output) {
  const std::string& name = output.name;
  if (output.folder.empty()) throw std::invalid_argument("this process was started without a folder for such files");
  const bool control = std::any_of(name.begin(), name.end(), [](char c) { return (unsigned char)c < 0x20 || c == 0x7f; });
  if (name.empty() || name.size() > kMaxNameBytes || control || name.find('/') != std::string::npos ||
      name.find("..") != std::string::npos)
    throw std::invalid_argument("not a plain file name (no '/', no '..', no control characters, at most " +
                                std::to_string(kMaxNameBytes) + " bytes); files go only into " + output.folder);
  if (name.size() <= output.extension.size() ||
      name.compare(name.size() - output.extension.size(), std::string::npos, output.extension) != 0)
    throw std::invalid_argument("this command writes only " + output.extension + " files");
  const std::string path = (std::filesystem::path(output.folder) / name).string();
  if (!output.overwrite && PathExists(path))
    throw std::invalid_argument(path + " exists; overwrite=1 replaces it and keeps the old one as a backup");
  return path;
}

std::string KeepBackup(const std::string& path) {
  if (!PathExists(path)) return "";
  // The numbers of PATH.N.bak there now.
  const std::filesystem::path file(path);
  const std::string prefix = file.filename().string() + ".";
  std::vector<long> kept;
  std::error_code error;
  const std::filesystem::path folder = file.parent_path().empty() ? "." : file.parent_path();
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= prefix.size() + 4 || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - 4, 4, ".bak") != 0)
      continue;
    const std::string number = name.substr(prefix.size(), name.size() - prefix.size() - 4);
    if (number.empty() || number.size() > 9 || number.find_first_not_of("0123456789") != std::string::npos) continue;
    kept.push_back(std::stol(number));
  }
  const long next = kept.empty() ? 1 : *std::max_element(kept.begin(), kept.end()) + 1;
  const std::string backup = path + "." + std::to_string(next) + ".bak";
  if (link(path.c_str(), backup.c_str()) != 0)
    throw std::runtime_error("cannot keep a backup of " + path + ": " + std::strerror(errno));
  for (long n : kept)  // the oldest beyond the last kKeptBackups
    if (n <= next - kKeptBackups) std::filesystem::remove(path + "." + std::to_string(n) + ".bak", error);
  return backup;
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
