// Board corners detected by other tools, read as one camera's views, so that
// their detections can be calibrated here (and compared on equal terms).
//
// BabelCalib (Lochman et al., ICCV 2021; ../shared/data/README.md):
//   target.dsc   line 1 "board, columns, rows, size"; line 2 the tag family;
//                then one fiducial a line "id, column, row, X, Y, Z" (id -1:
//                a chessboard corner), board units;
//   image.orpc   a header of "key: value" lines (filename, width, height,
//                num_corners, encoding: ascii), then one corner a line
//                "board, corner, marker, u, v" (pixels), `corner` the
//                0-based index of its fiducial in the .dsc list (BabelCalib's
//                own reader calls the fields camera, corner and marker id;
//                ../shared/data/README.md's "column, row" for them does not
//                match its files, whose third field is 1 throughout).
// mrcal (mrcal-calibrate-cameras --corners-cache):
//   corners.vnl  "# filename x y level", then one line a corner of every
//                image, each image's COLS x ROWS corners in row-major board
//                order; a level of "-" (or x, y of "-") marks a corner not
//                seen, and an image whose board was not found is one line
//                "filename - - -". The board is the chessboard of BoardSpec (square
//                size in metres); the image size is not in the file.
//                One file may hold several cameras' images: two globs
//                (glob_captures.h) pair a left and a right image when every
//                `*` of the two matched the same text, as
//                mrcal-calibrate-cameras pairs them.
// Errors name the file and line: CornerImportError.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "calib/solver/calib_data.h"

namespace ws::calib {

struct CornerImportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The views of the .orpc files, in the order given, on the .dsc target.
CameraData ReadBabelCalibViews(const std::string& dsc_path,
                               const std::vector<std::string>& orpc_paths);

// One image's corners in a corners.vnl (an empty view: the board was not found).
struct NamedView {
  std::string name;
  BoardView view;
};

// Every image of a corners.vnl in the file's order, on the chessboard of
// cols x rows inner corners with squares of `square` metres.
std::vector<NamedView> ReadMrcalViews(const std::string& vnl_path, int cols, int rows, double square);

// The views of a corners.vnl as one camera, images in the file's order;
// `names` (if not null) receives each view's file name.
CameraData ReadMrcalCorners(const std::string& vnl_path, int cols, int rows, double square,
                            int image_width, int image_height,
                            std::vector<std::string>* names = nullptr);

// The images of `views` paired into stereo frames: an image matching
// left_glob is a left view, one matching right_glob a right view, and a left
// and a right view form one frame when each `*` of the two globs matched the
// same text. A frame seen by one camera only keeps an empty view for the
// other. Frames are in the order their first image appears. Both cameras
// get the image size given. Throws CornerImportError when the globs have
// different numbers of `*`, an image matches both globs, or two images of
// one camera would fall in the same frame.
struct PairedViews {
  StereoData data;
  std::vector<std::string> left_names, right_names;  // per frame; "" where the camera has no image
  int unmatched = 0;                                 // images matching neither glob (not used)
};
PairedViews PairMrcalViews(const std::vector<NamedView>& views, const std::string& left_glob,
                           const std::string& right_glob, int image_width, int image_height);

}  // namespace ws::calib
