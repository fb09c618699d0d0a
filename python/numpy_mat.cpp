#include "numpy_mat.h"

#include <cstring>
#include <stdexcept>

namespace py = pybind11;

namespace ws::python {
namespace {

py::dtype DtypeOf(int depth) {
  switch (depth) {
    case CV_8U: return py::dtype::of<uint8_t>();
    case CV_8S: return py::dtype::of<int8_t>();
    case CV_16U: return py::dtype::of<uint16_t>();
    case CV_16S: return py::dtype::of<int16_t>();
    case CV_32S: return py::dtype::of<int32_t>();
    case CV_32F: return py::dtype::of<float>();
    case CV_64F: return py::dtype::of<double>();
  }
  throw std::invalid_argument("an OpenCV matrix of an unsupported depth");
}

int DepthOf(const py::dtype& dtype) {
  for (int depth : {CV_8U, CV_8S, CV_16U, CV_16S, CV_32S, CV_32F, CV_64F})
    if (dtype.is(DtypeOf(depth))) return depth;
  throw std::invalid_argument("an array of dtype " + py::str(static_cast<const py::handle&>(dtype)).cast<std::string>() +
                              " (uint8, int8, uint16, int16, int32, float32 or float64)");
}

}  // namespace

py::array MatToArray(const cv::Mat& mat) {
  const cv::Mat m = mat.isContinuous() ? mat : mat.clone();
  std::vector<py::ssize_t> shape{m.rows, m.cols};
  if (m.channels() > 1) shape.push_back(m.channels());
  py::array out(DtypeOf(m.depth()), shape);
  std::memcpy(out.mutable_data(), m.data, m.total() * m.elemSize());
  return out;
}

cv::Mat ArrayToMat(const py::array& array) {
  const py::array a = py::array::ensure(array, py::array::c_style);
  if (!a || (a.ndim() != 2 && a.ndim() != 3))
    throw std::invalid_argument("an image must be a 2-D or H x W x C array");
  const int channels = a.ndim() == 3 ? int(a.shape(2)) : 1;
  if (channels < 1 || channels > 4) throw std::invalid_argument("an image has 1 to 4 channels");
  cv::Mat mat(int(a.shape(0)), int(a.shape(1)), CV_MAKETYPE(DepthOf(a.dtype()), channels));
  std::memcpy(mat.data, a.data(), mat.total() * mat.elemSize());
  return mat;
}

}  // namespace ws::python
