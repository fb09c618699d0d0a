// Typed, checked reading of the YAML files widestereo writes with
// cv::FileStorage (the calibration file, rig/rig_file.h; the simulator's
// truth, sim/ground_truth.h): every field present, of its type, finite and
// of a bounded size before anything is allocated, and every refusal a
// YamlFieldError "FILE: FIELD: REASON".
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace ws {

struct YamlFieldError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class YamlReader {
 public:
  // `rewrite`: how to write the file again, said when it was cut short
  // (it ends mid-line), e.g. "with stereo-calibrate --out".
  YamlReader(std::string path, std::string rewrite);

  // Opens the file (runtime/opencv_yaml.h: bounded, its layout checked)
  // and returns its top-level map.
  cv::FileNode Open(cv::FileStorage& fs, size_t max_bytes) const;

  [[noreturn]] void Fail(const std::string& field, const std::string& reason) const;
  cv::FileNode Required(const cv::FileNode& parent, const std::string& key, const std::string& field) const;
  // A map under `key`.
  cv::FileNode Map(const cv::FileNode& parent, const std::string& key, const std::string& field) const;
  int Int(const cv::FileNode& parent, const std::string& key, const std::string& field, int min) const;
  double Real(const cv::FileNode& parent, const std::string& key, const std::string& field) const;
  std::string String(const cv::FileNode& parent, const std::string& key, const std::string& field) const;
  // At most `max_count` numbers: a 1 x N or N x 1 !!opencv-matrix of
  // doubles or floats, or a list.
  std::vector<double> Reals(const cv::FileNode& parent, const std::string& key, const std::string& field,
                            size_t max_count) const;
  // A rows x cols !!opencv-matrix of finite numbers.
  Eigen::MatrixXd Matrix(const cv::FileNode& parent, const std::string& key, const std::string& field, int rows,
                         int cols) const;

 private:
  double Number(const cv::FileNode& node, const std::string& field) const;

  std::string path_, rewrite_;
  bool cut_short_;
};

}  // namespace ws
