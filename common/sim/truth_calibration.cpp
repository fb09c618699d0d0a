#include "sim/truth_calibration.h"

#include <opencv2/core/eigen.hpp>

namespace ws {

calib::CalibrationFile TrueCalibration(const SimTruth& truth) {
  calib::CalibrationFile file;
  file.model = truth.left.distortion.kind;
  file.left = truth.left;
  file.right = truth.right;
  cv::cv2eigen(cv::Mat(truth.R), file.R);
  cv::cv2eigen(cv::Mat(truth.T), file.T);
  return file;
}

}  // namespace ws
