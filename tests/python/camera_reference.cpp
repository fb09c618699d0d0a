// The C++ side of tests/python/test_camera.py: one camera of every model
// kind as a one-camera calibration file, DIR/KIND.yaml, and what the C++
// Camera gives on it, DIR/KIND.txt: a line "u v X Y Z" for every pixel of a
// 16 x 12 grid over the whole image with its unit ray (nan where none), and
// a line "X Y Z u v" for each of those rays turned by up to 5 degrees with
// the pixel Project gives. The Python module must give the same numbers.
// And DIR/rig-KIND.yaml, a stereo rig of two such cameras 12 cm apart, for
// the export tests.
//   camera_reference DIR
#include <cstdio>
#include <string>

#include <Eigen/Geometry>

#include "calib/calib_file.h"
#include "test_cameras.h"

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]) == "--help") {
    std::printf("camera_reference DIR: writes DIR/KIND.yaml and DIR/KIND.txt for every model kind\n");
    return argc == 2 ? 0 : 2;
  }
  const std::string dir = argv[1];
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.08, Eigen::Vector3d(1, 2, 0.5).normalized()).toRotationMatrix();
  for (const ws::CameraModel& model : ws::testing::KindCameras()) {
    const std::string kind = ws::ModelName(model.distortion.kind);
    ws::calib::CalibrationFile file;
    file.model = model.distortion.kind;
    file.mono = true;
    file.left = model;
    ws::calib::WriteCalibrationFile(dir + "/" + kind + ".yaml", file);
    ws::calib::CalibrationFile rig = file;
    rig.mono = false;
    rig.right = model;
    rig.right.cx += 3.5;
    rig.R = Eigen::AngleAxisd(0.01, Eigen::Vector3d(0.2, 1, 0.1).normalized()).toRotationMatrix();
    rig.T = Eigen::Vector3d(-0.12, 0.001, 0.002);
    ws::calib::WriteCalibrationFile(dir + "/rig-" + kind + ".yaml", rig);
    const ws::Camera camera(ws::calib::ReadCalibrationFile(dir + "/" + kind + ".yaml").left);
    FILE* out = std::fopen((dir + "/" + kind + ".txt").c_str(), "w");
    if (!out) return 1;
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 16; ++i) {
        const Eigen::Vector2d pixel(i * (model.image_width - 1) / 15.0, j * (model.image_height - 1) / 11.0);
        const auto ray = camera.Unproject(pixel);
        const Eigen::Vector3d r = ray ? *ray : Eigen::Vector3d::Constant(NAN);
        std::fprintf(out, "unproject %.17g %.17g %.17g %.17g %.17g\n", pixel.x(), pixel.y(), r.x(), r.y(), r.z());
        if (!ray) continue;
        const Eigen::Vector3d point = 2.5 * (turn * r);
        const auto projected = camera.Project(point);
        const Eigen::Vector2d q = projected ? *projected : Eigen::Vector2d::Constant(NAN);
        std::fprintf(out, "project %.17g %.17g %.17g %.17g %.17g\n", point.x(), point.y(), point.z(), q.x(), q.y());
      }
    std::fclose(out);
  }
  return 0;
}
