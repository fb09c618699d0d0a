// _widestereo: the C++ side of the Python module widestereo (docs/python.md).
// Every number comes from the library itself: Camera::Project and
// Unproject, ReadCalibrationFile and the other tools' readers
// (interop/any_rig.h), BuildRectification, TriangulatePixels and
// TriangulateDisparity; this file only loops over numpy arrays.
#include <cmath>
#include <memory>
#include <string>
#include <type_traits>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "interop/any_rig.h"
#include "models/camera_field_table.h"
#include "numpy_mat.h"
#include "rectify/pair_triangulation.h"
#include "rectify/ray_triangulation.h"
#include "rectify/rectification.h"
#include "rig/rig_message.h"

namespace py = pybind11;

namespace ws::python {
namespace {

using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

// An N x `in` array (or one row of `in`) mapped row by row to N x `out`
// (or one row), NaN where `map` has no value.
template <int In, int Out, class Map>
py::array_t<double> MapRows(const Points& points, const char* what, const Map& map) {
  const bool single = points.ndim() == 1;
  if (!(single ? points.shape(0) == In : points.ndim() == 2 && points.shape(1) == In))
    throw std::invalid_argument(std::string(what) + " must be an N x " + std::to_string(In) +
                                " array (or " + std::to_string(In) + " numbers)");
  const py::ssize_t n = single ? 1 : points.shape(0);
  py::array_t<double> out(single ? std::vector<py::ssize_t>{Out} : std::vector<py::ssize_t>{n, Out});
  const double* in = points.data();
  double* o = out.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) {
      const auto value = map(Eigen::Map<const Eigen::Matrix<double, In, 1>>(in + In * i), i);
      for (int k = 0; k < Out; ++k) o[Out * i + k] = value ? (*value)[k] : NAN;
    }
  }
  return out;
}

// A camera of any format (interop/camera_projection.h).
struct PyCamera {
  std::shared_ptr<const CameraProjection> camera;

  py::array_t<double> Project(const Points& points) const {
    return MapRows<3, 2>(points, "points", [&](const Eigen::Vector3d& p, py::ssize_t) {
      return camera->Project(p);
    });
  }
  py::array_t<double> Unproject(const Points& pixels) const {
    return MapRows<2, 3>(pixels, "pixels", [&](const Eigen::Vector2d& q, py::ssize_t) {
      return camera->Unproject(q);
    });
  }
  // CameraProjection::InField per row.
  py::array_t<bool> InField(const Points& rays) const {
    if (rays.ndim() != 2 || rays.shape(1) != 3) throw std::invalid_argument("rays must be an N x 3 array");
    py::array_t<bool> out(rays.shape(0));
    for (py::ssize_t i = 0; i < rays.shape(0); ++i)
      out.mutable_data()[i] = camera->InField(Eigen::Map<const Eigen::Vector3d>(rays.data() + 3 * i));
    return out;
  }
  // widestereo's parameters, or None: the calibration file's fields, as
  // models/camera_field_table.h names them (fx fy cx cy apart).
  py::object Parameters() const {
    const Camera* own = camera->AsCamera();
    if (!own) return py::none();
    return Fields([&](auto&& visit) { ForEachCameraField(own->model(), visit); });
  }

 private:
  // The fields a visit of the camera table gives, as a dict: the model by
  // its name, the non-radial part a dict of its own.
  template <class ForEach>
  static py::dict Fields(ForEach&& for_each) {
    py::dict d;
    for_each([&](const std::string& key, const auto& value) {
      using T = std::decay_t<decltype(value)>;
      if constexpr (std::is_same_v<T, NonRadial>)
        d[key.c_str()] = Fields([&](auto&& visit) { ForEachNonRadialField(value, visit); });
      else if constexpr (std::is_same_v<T, ModelKind>)
        d[key.c_str()] = ModelName(value);
      else
        d[key.c_str()] = value;
    });
    return d;
  }
};

const std::shared_ptr<const CameraProjection>& Side(const AnyRig& rig, const std::string& side,
                                                    const std::string& path) {
  if (side == "left") return rig.left;
  if (side == "right") {
    if (rig.mono) throw std::invalid_argument(path + " holds one camera only ('left')");
    return rig.right;
  }
  throw std::invalid_argument("side must be 'left' or 'right', not '" + side + "'");
}

struct PyRig {
  AnyRig rig;

  static PyRig FromMessage(const py::bytes& encoded) {
    const std::string data = encoded;
    widestereo::stereo_calibration_t msg;
    if (msg.decode(data.data(), 0, int(data.size())) != int(data.size()))
      throw std::invalid_argument("not an encoded stereo_calibration_t");
    const Rig stereo = RigFromMessage(msg);
    PyRig out;
    out.rig.format = "message";
    out.rig.left = std::make_shared<WidestereoProjection>(stereo.left);
    out.rig.right = std::make_shared<WidestereoProjection>(stereo.right);
    out.rig.R = stereo.R;
    out.rig.T = stereo.T;
    return out;
  }

  PyCamera Get(const std::string& side) const { return {Side(rig, side, "the rig")}; }

  Rectification Rectify(const std::string& mode, double focal_scale,
                        const std::optional<std::pair<int, int>>& size) const {
    RectifyOptions options;
    options.mode = ParseRectificationMode(mode);
    options.focal_scale = focal_scale;
    if (size && (size->first <= 0 || size->second <= 0))
      throw std::invalid_argument("size must be two positive numbers (width, height), or None for the default");
    if (size) options.size = cv::Size(size->first, size->second);
    const Rig stereo = rig.AsStereoRig();
    py::gil_scoped_release release;
    return BuildRectification(stereo, options);
  }

  py::array_t<double> Triangulate(const Points& left, const Points& right) const {
    const Rig stereo = rig.AsStereoRig();
    if (left.ndim() != right.ndim() || left.size() != right.size())
      throw std::invalid_argument("left and right pixels must be arrays of the same shape");
    const Points r = right;
    const Camera cl(stereo.left), cr(stereo.right);
    return MapRows<2, 3>(left, "left pixels", [&](const Eigen::Vector2d& q, py::ssize_t i) {
      const Eigen::Vector2d qr(r.data()[2 * i], r.data()[2 * i + 1]);
      return TriangulatePixels(cl, cr, stereo.R, stereo.T, q, qr);
    });
  }
};

// A path as Python gave it: one with a NUL byte would name another file
// (the C library stops at it), so it is refused.
const std::string& CheckedPath(const std::string& path) {
  if (path.find('\0') != std::string::npos) throw std::invalid_argument("a path with a NUL byte names no file");
  return path;
}

py::tuple Maps(const std::array<cv::Mat, 2>& maps) { return py::make_tuple(MatToArray(maps[0]), MatToArray(maps[1])); }

py::array_t<double> Matrix(const double* values, int rows, int cols) {
  py::array_t<double> out({rows, cols});
  std::copy(values, values + rows * cols, out.mutable_data());
  return out;
}

}  // namespace
}  // namespace ws::python

using namespace ws;
using namespace ws::python;

PYBIND11_MODULE(_widestereo, m) {
  m.doc() = "widestereo's camera models, rectification and triangulation (docs/python.md)";

  py::class_<PyCamera>(m, "Camera",
                       "One camera of a calibration: widestereo's file, or another tool's "
                       "(mrcal .cameramodel, Kalibr camchain, OpenCV calibration YAML, ROS camera_info, "
                       "any folder stereo-export writes)")
      .def_static(
          "load",
          [](const std::string& path, const std::string& side) {
            const AnyRig rig = LoadAnyRig(CheckedPath(path));
            return PyCamera{Side(rig, side, path)};
          },
          py::arg("path"), py::arg("side") = "left",
          "The camera 'left' or 'right' of the calibration at path (any format the module reads)")
      .def("project", &PyCamera::Project, py::arg("points"),
           "N x 3 camera-frame points (or directions) -> N x 2 pixels; NaN where the model has none")
      .def("unproject", &PyCamera::Unproject, py::arg("pixels"),
           "N x 2 pixels -> N x 3 unit rays; NaN where the model cannot be inverted")
      .def("in_field", &PyCamera::InField, py::arg("rays"),
           "N x 3 directions -> N booleans: within the field the model was calibrated over "
           "(a B-spline's knots; for the others, imaged inside the image before the model folds)")
      .def_property_readonly("image_size",
                             [](const PyCamera& c) {
                               return py::make_tuple(c.camera->image_width(), c.camera->image_height());
                             })
      .def_property_readonly("model", [](const PyCamera& c) { return c.camera->Name(); })
      .def_property_readonly("parameters", &PyCamera::Parameters,
                             "widestereo's model parameters as a dict; None for another tool's model");

  py::class_<Rectification>(m, "Rectification",
                            "Both cameras' rectification (pinhole or lat-lon), the maps stereo-match uses")
      .def_property_readonly("mode", [](const Rectification& r) { return RectificationModeName(r.mode); })
      .def_property_readonly("size", [](const Rectification& r) { return py::make_tuple(r.size.width, r.size.height); })
      .def_readonly("f", &Rectification::f)
      .def_readonly("cx", &Rectification::cx)
      .def_readonly("cy", &Rectification::cy)
      .def_readonly("baseline", &Rectification::baseline)
      .def_property_readonly("Q", [](const Rectification& r) { return Matrix(r.Q.val, 4, 4); })
      .def_property_readonly("R_left", [](const Rectification& r) { return Matrix(r.R_left.val, 3, 3); })
      .def_property_readonly("R_right", [](const Rectification& r) { return Matrix(r.R_right.val, 3, 3); })
      .def_property_readonly("maps_left", [](const Rectification& r) { return Maps(r.maps_left.front()); },
                             "(map1, map2): OpenCV's fixed-point tables for cv2.remap(image, map1, map2, cv2.INTER_LINEAR)")
      .def_property_readonly("maps_right", [](const Rectification& r) { return Maps(r.maps_right.front()); })
      .def_property_readonly("valid_left", [](const Rectification& r) { return MatToArray(r.valid_left); })
      .def_property_readonly("valid_right", [](const Rectification& r) { return MatToArray(r.valid_right); })
      .def(
          "rectify",
          [](const Rectification& r, const py::array& left, const py::array& right) {
            const cv::Mat l = ArrayToMat(left), rt = ArrayToMat(right);
            for (const cv::Mat* image : {&l, &rt})
              if (image->size() != r.input_size)
                throw std::invalid_argument("an image of " + std::to_string(image->cols) + "x" +
                                            std::to_string(image->rows) + ", where the cameras' are " +
                                            std::to_string(r.input_size.width) + "x" +
                                            std::to_string(r.input_size.height));
            cv::Mat out_left, out_right;
            RectifyPair(r, l, rt, &out_left, &out_right);
            return py::make_tuple(MatToArray(out_left), MatToArray(out_right));
          },
          py::arg("left"), py::arg("right"), "Both images rectified (as stereo-match does)")
      .def(
          "triangulate",
          [](const Rectification& r, const Points& uvd) {
            return MapRows<3, 3>(uvd, "(u, v, disparity) rows", [&](const Eigen::Vector3d& p, py::ssize_t) {
              const auto point = TriangulateDisparity(r, p[0], p[1], p[2]);
              return point ? std::optional<Eigen::Vector3d>(Eigen::Vector3d((*point)[0], (*point)[1], (*point)[2]))
                           : std::nullopt;
            });
          },
          py::arg("uvd"),
          "N x 3 (u, v, disparity) of the left rectified image -> N x 3 points of the left rectified frame");

  py::class_<PyRig>(m, "Rig", "A calibrated camera pair, X_right = R X_left + T")
      .def_static(
          "load", [](const std::string& path) { return PyRig{LoadAnyRig(CheckedPath(path))}; }, py::arg("path"))
      .def_static("from_message", &PyRig::FromMessage, py::arg("encoded"),
                  "The rig of an encoded stereo_calibration_t (STEREO_CALIBRATION)")
      .def_property_readonly("left", [](const PyRig& r) { return r.Get("left"); })
      .def_property_readonly("right", [](const PyRig& r) { return r.Get("right"); })
      .def_property_readonly("R", [](const PyRig& r) { return Eigen::Matrix3d(r.rig.R); })
      .def_property_readonly("T", [](const PyRig& r) { return Eigen::Vector3d(r.rig.T); })
      .def_property_readonly("format", [](const PyRig& r) { return r.rig.format; })
      .def("rectification", &PyRig::Rectify, py::arg("mode") = "pinhole", py::arg("focal_scale") = 1.0,
           py::arg("size") = std::nullopt, "mode: 'pinhole', 'latlon' or 'auto'")
      .def("triangulate", &PyRig::Triangulate, py::arg("left_pixels"), py::arg("right_pixels"),
           "N x 2 left and right pixels of matches -> N x 3 points of the left camera frame (metres); "
           "NaN where the rays do not meet in front of both cameras");
}
