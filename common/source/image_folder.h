// The layouts a folder of calibration images comes in, as cameras and tools
// write them:
//
//   left-right names   left01.jpg + right01.jpg in the folder itself (names
//                      that differ only in "left" and "right")
//   left/ + right/     two subfolders, an image's partner the one whose name
//                      is the same once "left"/"right" is taken out of both
//   cam0/ + cam1/      likewise (Kalibr and EuRoC; cam0/data/ + cam1/data/ too)
//   one camera         any other folder of images: each image alone
//
// Pairs come in the sorted order of their left names. An image whose partner
// is missing is no pair: it is listed in `unpaired`, never used in silence.
#pragma once

#include <string>
#include <vector>

namespace ws {

struct ImagePairPaths {
  std::string left;
  std::string right;  // "" for a one-camera folder
};

enum class FolderLayout { kLeftRightNames, kLeftRightFolders, kCamFolders, kOneCamera };

struct ImageFolder {
  FolderLayout layout = FolderLayout::kOneCamera;
  std::vector<ImagePairPaths> pairs;
  std::vector<std::string> unpaired;  // images without their partner, sorted
};

// "left01.jpg + right01.jpg names", "left/ + right/ folders", ... for messages.
std::string LayoutName(FolderLayout layout);

// The images of `dir` in the first layout above that it holds, or with
// `one_camera` every image of the folder itself alone. Throws
// std::runtime_error when the folder cannot be read, holds no image, or (in a
// stereo layout) no image has its partner.
ImageFolder FindImageFolder(const std::string& dir, bool one_camera = false);

// A file's name for messages: "left01.jpg", "left/0001.png" for a subfolder.
std::string ImageName(const std::string& path, const std::string& dir);

}  // namespace ws
