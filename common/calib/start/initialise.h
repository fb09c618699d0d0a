// The start of a camera's calibration: its usable views, and Zhang's
// closed form on them (homography.h): pinhole intrinsics and a pose per view.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "calib/solver/calib_data.h"
#include "calib/solver/camera_block.h"
#include "calib/solver/options.h"
#include "calib/solver/pose.h"
#include "calib/start/homography.h"

namespace ws::calib {

// A camera's views after cleaning, with which can be used and why not.
struct Prepared {
  std::string name;
  int width = 0, height = 0;
  std::vector<BoardView> views;  // non-finite corners dropped
  std::vector<bool> usable;
  std::vector<std::string> skipped;  // "view 3: ..."
  int invalid_points = 0;            // non-finite corners dropped

  int NumUsable() const;
  void Skip(int view, const std::string& why);
};

// Cleans every view (CleanView) and marks those ViewProblem rejects.
Prepared Prepare(const CameraData& data, const CalibrationOptions& options);

// Throws CalibrationError (listing why views were skipped) unless at least
// min_views views are usable.
void RequireViews(const Prepared& prepared, int min_views);

// The lens a start assumes: a pinhole (Zhang's, or an angle model's
// perspective start) or the equidistant fisheye (angle_start.h).
enum class StartLens { kPerspective, kEquidistant };

struct Init {
  PinholeInit pinhole;
  StartLens lens = StartLens::kPerspective;
  std::vector<Pose> poses;                    // per view (usable ones)
  std::vector<Eigen::Matrix3d> homographies;  // per view (usable ones)
};

// Homographies, Zhang's intrinsics and each view's pose; views whose
// homography fails or whose pose puts the board behind the camera are
// skipped. For an angle model `kind` (kb4, bspline_theta) the start of
// angle_start.h instead, with no homographies. Throws CalibrationError when
// too few views remain or when the board planes are all within
// options.min_view_angle_deg of parallel. With `shared`, an angle model's
// start is the one every angle model of these views shares.
class SharedAngleStart;
Init Initialize(Prepared& prepared, const CalibrationOptions& options, ModelKind kind,
                SharedAngleStart* shared = nullptr);

// The camera of the start: the model of `kind` with only fx fy cx cy free
// (PinholeBlock) on the start's lens: D = 0 (a pinhole for the
// tan(theta) models, the equidistant fisheye for the angle models), or for
// an angle model on the perspective lens the closest D(theta) to
// tan(theta) / theta - 1 (r = f tan(theta)) up to the angle of the image's
// corner.
CameraBlock StartCamera(const Init& init, const Prepared& prepared, ModelKind kind,
                        const SplineOptions& spline);

// The pose of view `view` from its homography under the pinhole (fx, fy,
// cx, cy); false when it puts the board behind the camera.
bool HomographyPose(const Init& init, const Prepared& prepared, int view, const double* intrinsics,
                    Pose* pose);

}  // namespace ws::calib
