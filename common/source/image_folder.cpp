#include "source/image_folder.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

namespace ws {
namespace {

namespace fs = std::filesystem;

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

bool IsImage(const fs::path& path) {
  static const std::set<std::string> kExtensions = {".jpg", ".jpeg", ".png", ".bmp", ".pgm",
                                                    ".ppm", ".pnm", ".tif", ".tiff"};
  return kExtensions.count(Lower(path.extension().string())) > 0;
}

// The images directly in `dir`, sorted.
std::vector<std::string> ImagesIn(const fs::path& dir) {
  std::error_code error;
  fs::directory_iterator it(dir, error);
  if (error) throw std::runtime_error("cannot read image folder " + dir.string() + ": " + error.message());
  std::vector<std::string> images;
  // Whatever bears an image's name but a folder: a device, a FIFO or a
  // symlink loop is then named and left out by its reader (dir_source.h),
  // not skipped in silence or fatal here.
  for (const auto& entry : it) {
    std::error_code not_a_folder;
    if (IsImage(entry.path()) && !entry.is_directory(not_a_folder)) images.push_back(entry.path().string());
  }
  std::sort(images.begin(), images.end());
  return images;
}

// The file name with the first `token` (any case) marked, or "" when it has
// none: the key an image shares with its partner.
std::string PairKey(const std::string& path, const std::string& token) {
  const std::string name = fs::path(path).filename().string();
  const size_t at = Lower(name).find(token);
  if (at == std::string::npos) return "";
  return name.substr(0, at) + '\x01' + name.substr(at + token.size());
}

// Pairs the images of two lists whose keys agree; the others are unpaired.
void Pair(const std::vector<std::string>& lefts, const std::string& left_token,
          const std::vector<std::string>& rights, const std::string& right_token, bool token_required,
          ImageFolder* folder) {
  auto key = [&](const std::string& path, const std::string& token) {
    const std::string marked = PairKey(path, token);
    return marked.empty() && !token_required ? fs::path(path).filename().string() : marked;
  };
  std::map<std::string, std::string> right_by_key;
  for (const std::string& right : rights) right_by_key[key(right, right_token)] = right;
  for (const std::string& left : lefts) {
    auto it = right_by_key.find(key(left, left_token));
    if (it == right_by_key.end()) {
      folder->unpaired.push_back(left);
    } else {
      folder->pairs.push_back({left, it->second});
      right_by_key.erase(it);
    }
  }
  for (const auto& [k, right] : right_by_key) folder->unpaired.push_back(right);
  std::sort(folder->unpaired.begin(), folder->unpaired.end());
}

// dir/NAME, or dir/NAME/data when that is where the images are (EuRoC).
fs::path CameraFolder(const fs::path& dir, const std::string& name) {
  const fs::path data = dir / name / "data";
  return fs::is_directory(data) ? data : dir / name;
}

}  // namespace

std::string LayoutName(FolderLayout layout) {
  switch (layout) {
    case FolderLayout::kLeftRightNames:
      return "left*/right* names in one folder";
    case FolderLayout::kLeftRightFolders:
      return "left/ + right/ folders";
    case FolderLayout::kCamFolders:
      return "cam0/ + cam1/ folders";
    case FolderLayout::kOneCamera:
      break;
  }
  return "one camera";
}

ImageFolder FindImageFolder(const std::string& dir, bool one_camera) {
  const fs::path root(dir);
  ImageFolder folder;
  if (!one_camera && fs::is_directory(root / "left") && fs::is_directory(root / "right")) {
    folder.layout = FolderLayout::kLeftRightFolders;
    Pair(ImagesIn(root / "left"), "left", ImagesIn(root / "right"), "right", false, &folder);
  } else if (!one_camera && fs::is_directory(root / "cam0") && fs::is_directory(root / "cam1")) {
    folder.layout = FolderLayout::kCamFolders;
    Pair(ImagesIn(CameraFolder(root, "cam0")), "cam0", ImagesIn(CameraFolder(root, "cam1")), "cam1", false,
         &folder);
  } else {
    const std::vector<std::string> images = ImagesIn(root);
    if (images.empty())
      throw std::runtime_error("no images in " + dir +
                               " (jpg, png, bmp, pgm, ppm, tif; or left/ + right/, cam0/ + cam1/ folders)");
    std::vector<std::string> lefts, rights;
    for (const std::string& image : images) {
      if (!PairKey(image, "left").empty())
        lefts.push_back(image);
      else if (!PairKey(image, "right").empty())
        rights.push_back(image);
      else
        folder.unpaired.push_back(image);
    }
    if (one_camera || (lefts.empty() && rights.empty())) {
      folder.layout = FolderLayout::kOneCamera;
      folder.unpaired.clear();
      for (const std::string& image : images) folder.pairs.push_back({image, ""});
      return folder;
    }
    folder.layout = FolderLayout::kLeftRightNames;
    Pair(lefts, "left", rights, "right", true, &folder);
  }
  if (folder.pairs.empty())
    throw std::runtime_error("no image in " + dir + " has its partner (" + LayoutName(folder.layout) +
                             ": partners' names differ only in left/right or cam0/cam1; " +
                             std::to_string(folder.unpaired.size()) +
                             " images alone); for a one-camera rig use --mono");
  return folder;
}

std::string ImageName(const std::string& path, const std::string& dir) {
  const fs::path relative = fs::path(path).lexically_relative(dir);
  return relative.empty() || *relative.begin() == ".." ? fs::path(path).filename().string() : relative.string();
}

}  // namespace ws
