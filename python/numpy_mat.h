// cv::Mat <-> numpy arrays for the Python module, copied both ways: 2-D
// arrays for one channel, H x W x C for several (8/16-bit integers and
// 32/64-bit floats, as OpenCV's own Python binding has them).
#pragma once

#include <opencv2/core.hpp>
#include <pybind11/numpy.h>

namespace ws::python {

pybind11::array MatToArray(const cv::Mat& mat);
// Throws std::invalid_argument for an array of another type or shape.
cv::Mat ArrayToMat(const pybind11::array& array);

}  // namespace ws::python
