// Loads a calibration, unprojects the left image's centre, puts a point 2 m
// along that ray, projects it into both cameras and triangulates it back
// from the two pixels; builds the rectification stereo-match would use.
//   use_calibration CALIB.yaml
#include <cstdio>
#include <string>

#include <widestereo/widestereo.h>

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]) == "--help") {
    std::printf("use_calibration CALIB.yaml: a point through both cameras and back\n");
    return argc == 2 ? 0 : 2;
  }
  try {
    const ws::StereoRig rig = ws::StereoRigFromFile(argv[1]);
    const ws::Camera left(rig.left), right(rig.right);
    const Eigen::Vector2d centre((rig.left.image_width - 1) / 2.0, (rig.left.image_height - 1) / 2.0);
    const Eigen::Vector3d point = 2.0 * left.Unproject(centre).value();
    const Eigen::Vector2d in_left = left.Project(point).value();
    const Eigen::Vector2d in_right = right.Project(rig.R * point + rig.T).value();
    const Eigen::Vector3d back =
        ws::TriangulatePixels(left, right, rig.R, rig.T, in_left, in_right).value();
    const ws::Rectification rect = ws::BuildRectification(rig);
    std::printf("%s: %s, baseline %.4f m\n", argv[1], ws::ModelName(rig.left.distortion.kind).c_str(), rig.T.norm());
    std::printf("point (%.4f, %.4f, %.4f) m: left pixel (%.3f, %.3f), right pixel (%.3f, %.3f)\n",
                point.x(), point.y(), point.z(), in_left.x(), in_left.y(), in_right.x(), in_right.y());
    std::printf("triangulated back (%.4f, %.4f, %.4f) m, off by %.3g m\n", back.x(), back.y(), back.z(),
                (back - point).norm());
    std::printf("pinhole rectification %dx%d, f %.2f px\n", rect.size.width, rect.size.height, rect.f);
    return (back - point).norm() < 1e-6 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "use_calibration: %s\n", e.what());
    return 1;
  }
}
