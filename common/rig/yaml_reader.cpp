#include "rig/yaml_reader.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "runtime/opencv_yaml.h"

namespace ws {
namespace {

// A file OpenCV wrote ends with a newline; one that does not was cut short.
bool EndsMidLine(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;  // never opens a FIFO (it would block)
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file || file.tellg() <= 0) return false;
  file.seekg(-1, std::ios::end);
  return file.get() != '\n';
}

}  // namespace

YamlReader::YamlReader(std::string path, std::string rewrite)
    : path_(std::move(path)), rewrite_(std::move(rewrite)), cut_short_(EndsMidLine(path_)) {}

cv::FileNode YamlReader::Open(cv::FileStorage& fs, size_t max_bytes) const {
  try {
    OpenOpenCvYaml(fs, path_, max_bytes);
  } catch (const YamlFileError& e) {
    Fail("(file)", e.what());
  }
  const cv::FileNode root = fs.root();
  if (!root.isMap()) Fail("(file)", "not a map of fields");
  return root;
}

void YamlReader::Fail(const std::string& field, const std::string& reason) const {
  throw YamlFieldError(path_ + ": " + field + ": " + reason +
                       (cut_short_ ? " (the file ends mid-line: it was cut short; write it again " + rewrite_ + ")"
                                   : ""));
}

cv::FileNode YamlReader::Required(const cv::FileNode& parent, const std::string& key,
                                  const std::string& field) const {
  const cv::FileNode node = parent[key];
  if (node.empty()) Fail(field, "missing");
  return node;
}

cv::FileNode YamlReader::Map(const cv::FileNode& parent, const std::string& key, const std::string& field) const {
  const cv::FileNode node = Required(parent, key, field);
  if (!node.isMap()) Fail(field, "not a map of fields");
  return node;
}

int YamlReader::Int(const cv::FileNode& parent, const std::string& key, const std::string& field, int min) const {
  const cv::FileNode node = Required(parent, key, field);
  if (!node.isInt()) Fail(field, "not an integer");
  const int value = static_cast<int>(node);
  if (value < min) Fail(field, std::to_string(value) + " is below " + std::to_string(min));
  return value;
}

double YamlReader::Real(const cv::FileNode& parent, const std::string& key, const std::string& field) const {
  return Number(Required(parent, key, field), field);
}

std::string YamlReader::String(const cv::FileNode& parent, const std::string& key,
                               const std::string& field) const {
  const cv::FileNode node = Required(parent, key, field);
  if (!node.isString()) Fail(field, "not a string");
  return static_cast<std::string>(node);
}

// Its size is checked before any number is read, and the numbers are read
// in one pass (FileNode's operator[] walks a list from its start: a long
// list read by index took quadratic time). The matrix form is what the
// coefficient vectors are written as, so that they load into a cv::Mat; the
// list is what they were written as before.
std::vector<double> YamlReader::Reals(const cv::FileNode& parent, const std::string& key, const std::string& field,
                                      size_t max_count) const {
  cv::FileNode node = Required(parent, key, field);
  if (node.isMap()) {
    const std::string vector = "not a 1 x N !!opencv-matrix of numbers";
    const cv::FileNode rows = node["rows"], cols = node["cols"], dt = node["dt"];
    if (!rows.isInt() || !cols.isInt() || !dt.isString() || (int(rows) != 1 && int(cols) != 1) || int(rows) < 0 ||
        int(cols) < 0 || (std::string(dt) != "d" && std::string(dt) != "f"))
      Fail(field, vector);
    const size_t count = size_t(int(rows)) * size_t(int(cols));
    if (count > max_count) Fail(field, "more than " + std::to_string(max_count) + " numbers");
    node = node["data"];
    if (!node.isSeq() || node.size() != count) Fail(field, vector);
  }
  if (!node.isSeq()) Fail(field, "not a list of numbers");
  if (node.size() > max_count) Fail(field, "more than " + std::to_string(max_count) + " numbers");
  std::vector<double> values;
  values.reserve(node.size());
  for (const cv::FileNode& value : node) values.push_back(Number(value, field + "[" + std::to_string(values.size()) + "]"));
  return values;
}

Eigen::MatrixXd YamlReader::Matrix(const cv::FileNode& parent, const std::string& key, const std::string& field,
                                   int rows, int cols) const {
  const cv::FileNode node = Required(parent, key, field);
  const std::string shape = "not a " + std::to_string(rows) + "x" + std::to_string(cols) + " !!opencv-matrix";
  // The size the file claims is checked first: OpenCV allocates it.
  if (!node.isMap() || !node["rows"].isInt() || !node["cols"].isInt() || int(node["rows"]) != rows ||
      int(node["cols"]) != cols)
    Fail(field, shape);
  cv::Mat mat;
  try {
    node >> mat;
  } catch (const cv::Exception&) {
    Fail(field, shape);
  }
  Eigen::MatrixXd out(rows, cols);
  if (rows * cols == 0) return out;
  if (mat.rows != rows || mat.cols != cols || mat.channels() != 1) Fail(field, shape);
  mat.convertTo(mat, CV_64F);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) out(r, c) = mat.at<double>(r, c);
  if (!out.allFinite()) Fail(field, "not finite");
  return out;
}

double YamlReader::Number(const cv::FileNode& node, const std::string& field) const {
  if (!node.isReal() && !node.isInt()) Fail(field, "not a number");
  const double value = static_cast<double>(node);
  if (!std::isfinite(value)) Fail(field, "not finite");
  return value;
}

}  // namespace ws
