// How good a calibration is: RMS, per-view RMS and the residual pattern per
// image region (a lens model that cannot follow the lens leaves a radial
// pattern: residuals pointing in or out, growing towards the periphery).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace ws::calib {

// One corner's reprojection: residual = projected - observed (pixels).
struct CornerResidual {
  int view = 0;
  int index = 0;  // the corner's position in its view
  int id = 0;
  Eigen::Vector2d observed{0, 0};
  Eigen::Vector2d residual{0, 0};
  bool outlier = false;
};

// sqrt(mean |residual|^2) over the inliers (0 when there are none).
double Rms(const std::vector<CornerResidual>& residuals);
// Per view 0..num_views-1 over its inliers; -1 for views with none.
std::vector<double> ViewRms(const std::vector<CornerResidual>& residuals, int num_views);

// The image cut into rows x cols cells; per cell the inliers' count, mean
// residual vector and RMS.
struct ResidualGrid {
  int rows = 0, cols = 0;
  int image_width = 0, image_height = 0;
  std::vector<int> count;             // row-major
  std::vector<Eigen::Vector2d> mean;  // mean residual
  std::vector<double> rms;            // 0 where count is 0

  int Cell(double u, double v) const;  // -1 outside the image
  Eigen::Vector2d CellCentre(int cell) const;
};
ResidualGrid MakeResidualGrid(const std::vector<CornerResidual>& residuals, int image_width,
                              int image_height, int rows, int cols);

// The median of `values` (the upper one of an even count); -1 when empty.
double Median(std::vector<double> values);

// Robust noise level: the per-coordinate sigma of Gaussian noise whose 2-D
// residual norms have the inliers' median (median |e| = 1.1774 sigma).
double RobustSigma(const std::vector<CornerResidual>& residuals);

// The per-coordinate RMS of the inliers' residuals: sqrt(sum |e|^2 / 2n).
double RmsSigma(const std::vector<CornerResidual>& residuals);

// Decides every corner anew, previous outliers included: an outlier when its
// |residual| exceeds threshold_px. Returns how many flags changed.
int MarkOutliers(std::vector<CornerResidual>& residuals, double threshold_px);

}  // namespace ws::calib
