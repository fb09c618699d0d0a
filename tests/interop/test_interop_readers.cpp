// Other tools' calibration files (interop/any_rig.h) as a user's file may
// be: each reader checks every field before use and names the file and the
// field it refuses; a written file reads back as the camera it was.
#include <gtest/gtest.h>

#include <fstream>

#include "interop/any_rig.h"
#include "interop/exact_model.h"
#include "interop/kalibr_camchain.h"
#include "interop/lens_circle.h"
#include "interop/mrcal_cameramodel.h"
#include "interop/python_literal.h"
#include "rig/rig_file.h"
#include "test_support.h"

namespace ws {
namespace {

std::string Write(const std::string& name, const std::string& text) {
  const std::string path = test::TempDir("interop") + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// The message of what `load` throws, or "" when it does not.
template <class Load>
std::string Refusal(const Load& load) {
  try {
    load();
  } catch (const CalibrationFileError& e) {
    return e.what();
  }
  return "";
}

TEST(PythonLiteral, ReadsWhatMrcalWrites) {
  const PyLiteral v = ParsePyLiteral(
      "# comment\n{\n 'lensmodel': 'LENSMODEL_OPENCV4', # note\n 'intrinsics': [ 1, 2.5, -3e-2, 4,],\n"
      " 'x': (True, False, None), 'b': b'P)h>@6', \"s\": 'it\\'s' ,}\n");
  ASSERT_EQ(v.kind, PyLiteral::Kind::kDict);
  EXPECT_EQ(v.entries.at("lensmodel").text, "LENSMODEL_OPENCV4");
  EXPECT_EQ(v.entries.at("intrinsics").items.size(), 4u);
  EXPECT_EQ(v.entries.at("intrinsics").items[2].number, -3e-2);
  EXPECT_EQ(v.entries.at("x").items[0].number, 1);
  EXPECT_EQ(v.entries.at("b").text, "P)h>@6");
  EXPECT_EQ(v.entries.at("s").text, "it's");
}

TEST(PythonLiteral, RefusesWhatIsNotOneSayingWhere) {
  for (const char* text : {"{'a': 1", "{'a' 1}", "[1, 2] 3", "{1: 2}", "'open", "{'a': @}", ""}) {
    EXPECT_THROW(ParsePyLiteral(text), std::invalid_argument) << text;
  }
  try {
    ParsePyLiteral("{\n'a': [1,\n2,,]}");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ParsePyLiteral(std::string(100, '[') + std::string(100, ']')), std::invalid_argument);
}

TEST(MrcalCameraModel, RefusesMissingFieldsWrongCountsAndUnknownModels) {
  const std::string good =
      "{'lensmodel': 'LENSMODEL_OPENCV4', 'intrinsics': [300, 300, 400, 250, 0.1, 0, 0, 0],"
      " 'extrinsics': [0, 0, 0, 0, 0, 0], 'imagersize': [800, 503]}";
  EXPECT_EQ(ReadMrcalCameraModel(Write("good.cameramodel", good)).width, 800);
  const std::pair<std::string, std::string> cases[] = {
      {"{'intrinsics': [1]}", "lensmodel: missing"},
      {"{'lensmodel': 'LENSMODEL_OPENCV4', 'intrinsics': [300, 300, 400, 250], 'extrinsics': [0,0,0,0,0,0],"
       " 'imagersize': [800, 503]}",
       "intrinsics: LENSMODEL_OPENCV4 has 8 intrinsics, the file 4"},
      {"{'lensmodel': 'LENSMODEL_CAHVOR', 'intrinsics': [1, 1, 1, 1], 'extrinsics': [0,0,0,0,0,0],"
       " 'imagersize': [800, 503]}",
       "is not one widestereo reads"},
      {"{'lensmodel': 'LENSMODEL_PINHOLE', 'intrinsics': [300, 300, 400, 250], 'extrinsics': [0,0,0],"
       " 'imagersize': [800, 503]}",
       "extrinsics: not 6 numbers"},
      {"{'lensmodel': 'LENSMODEL_PINHOLE', 'intrinsics': [300, 300, 400, 250], 'extrinsics': [0,0,0,0,0,0],"
       " 'imagersize': [800.5, 503]}",
       "imagersize: not two positive integers"},
      {"{'lensmodel': 'LENSMODEL_SPLINED_STEREOGRAPHIC_order=2_Nx=4_Ny=4_fov_x_deg=100',"
       " 'intrinsics': [1], 'extrinsics': [0,0,0,0,0,0], 'imagersize': [800, 503]}",
       "only order=3"},
      {"not python", "not a mrcal .cameramodel"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string message = Refusal([&] { ReadMrcalCameraModel(Write("bad.cameramodel", text)); });
    EXPECT_NE(message.find(expected), std::string::npos) << text << "\n -> " << message;
  }
}

TEST(KalibrCamchain, RefusesModelsItDoesNotReadNamingTheField) {
  const std::string cam =
      "  camera_model: pinhole\n  intrinsics: [300, 300, 400, 250]\n  distortion_model: radtan\n"
      "  distortion_coeffs: [0.1, 0.01, 0.001, 0.002]\n  resolution: [800, 503]\n";
  const AnyRig rig = LoadAnyRig(Write("camchain.yaml", "cam0:\n" + cam));
  EXPECT_EQ(rig.format, "kalibr");
  EXPECT_TRUE(rig.mono);
  const CameraModel& m = rig.left->AsCamera()->model();
  EXPECT_EQ(m.distortion.kind, ModelKind::kPoly6);
  EXPECT_EQ(m.p2, 0.002);
  const std::pair<std::string, std::string> cases[] = {
      {"cam0:\n  camera_model: omni\n", "cam0.camera_model: 'omni'"},
      {"cam0:\n" + std::string(cam).replace(cam.find("radtan"), 6, "fov"), "cam0.distortion_model: 'fov'"},
      {"cam0:\n" + std::string(cam).replace(cam.find("[800, 503]"), 10, "[800]"), "cam0.resolution: missing or not a list of 2"},
      {"cam0:\n" + cam + "cam1:\n" + cam, "cam1.T_cn_cnm1: missing"},
      {"cam0:\n" + cam + "cam1:\n  T_cn_cnm1: [[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]\n" + cam,
       "cam1.T_cn_cnm1: not a rigid transform"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string message = Refusal([&] { LoadAnyRig(Write("bad.yaml", text)); });
    EXPECT_NE(message.find(expected), std::string::npos) << text << "\n -> " << message;
  }
}

TEST(OpenCvCalibration, ReadsOneCameraAndRefusesWhatItCannotHold) {
  const std::string header = "%YAML:1.0\n---\n";
  const std::string K = "camera_matrix: !!opencv-matrix\n  rows: 3\n  cols: 3\n  dt: d\n  data: [300, 0, 400, 0, 300, 250, 0, 0, 1]\n";
  auto D = [](const std::string& data, int n) {
    return "distortion_coefficients: !!opencv-matrix\n  rows: 1\n  cols: " + std::to_string(n) +
           "\n  dt: d\n  data: [" + data + "]\n";
  };
  const std::string size = "image_width: 800\nimage_height: 503\n";
  const AnyRig five = LoadAnyRig(Write("five.yaml", header + size + K + D("0.1, 0.01, 0.001, 0.002, 0.003", 5)));
  EXPECT_EQ(five.format, "opencv");
  EXPECT_EQ(five.left->AsCamera()->model().distortion.coeffs[2], 0.003);
  const AnyRig eight = LoadAnyRig(Write("eight.yaml", header + size + K + D("0.1, 0.01, 0, 0, 0, 0.05, 0, 0", 8)));
  EXPECT_EQ(eight.left->AsCamera(), nullptr);
  EXPECT_EQ(eight.left->Name(), "opencv 8-coefficient");
  const std::pair<std::string, std::string> cases[] = {
      {header + K + D("0, 0, 0, 0", 4), "image_width: missing"},
      {header + size + K + D("0, 0, 0", 3), "distortion_coefficients: 3 coefficients"},
      {header + size + "distortion_model: kannala\n" + K + D("0, 0, 0, 0", 4), "distortion_model: 'kannala'"},
      {header + size + K, "distortion_coefficients: missing"},
      {header + size + K + D("0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0", 15),
       "distortion_coefficients: more than 14 numbers"},
      {header + size + "camera_matrix: [300, 0, 400]\n" + D("0, 0, 0, 0", 4), "camera_matrix: "},
  };
  for (const auto& [text, expected] : cases) {
    const std::string message = Refusal([&] { LoadAnyRig(Write("bad.yml", text)); });
    EXPECT_NE(message.find(expected), std::string::npos) << text << "\n -> " << message;
  }
}

TEST(ExactTargetModel, OnlyModelsTheFormatHas) {
  CameraModel poly6;
  poly6.distortion = Distortion{ModelKind::kPoly6, 0, {}, {0.1, 0.01, 0.001}};
  poly6.p1 = 0.002, poly6.p2 = 0.003;
  EXPECT_EQ(ExactTargetModel(poly6, ExportFormat::kRos)->name, "plumb_bob");
  EXPECT_EQ(ExactTargetModel(poly6, ExportFormat::kRos)->coeffs, (std::vector<double>{0.1, 0.01, 0.002, 0.003, 0.001}));
  EXPECT_EQ(ExactTargetModel(poly6, ExportFormat::kMrcal)->name, "LENSMODEL_OPENCV5");
  EXPECT_FALSE(ExactTargetModel(poly6, ExportFormat::kKalibr));  // radtan has no k3
  CameraModel poly12 = poly6;
  poly12.distortion = Distortion{ModelKind::kPoly12, 0, {}, {0.1, 0.01, 0.001, 0, 0, 0}};
  EXPECT_EQ(ExactTargetModel(poly12, ExportFormat::kOpenCv)->coeffs.size(), 5u);
  poly12.distortion.coeffs[5] = 1e-6;
  EXPECT_FALSE(ExactTargetModel(poly12, ExportFormat::kOpenCv));
  CameraModel kb4;
  kb4.distortion = Distortion{ModelKind::kKb4, 0, {}, {0.1, 0.01, 0.001, 0.0001}};
  EXPECT_EQ(ExactTargetModel(kb4, ExportFormat::kOpenCv)->name, "fisheye");
  EXPECT_EQ(ExactTargetModel(kb4, ExportFormat::kKalibr)->name, "equidistant");
  EXPECT_FALSE(ExactTargetModel(kb4, ExportFormat::kMrcal));
  CameraModel tilted = poly6;  // OpenCV's and ROS's 14 coefficients; Kalibr and mrcal have no tilt
  tilted.nonradial.tilt = {0.01, -0.02};
  const std::vector<double> d14{0.1, 0.01, 0.002, 0.003, 0.001, 0, 0, 0, 0, 0, 0, 0, 0.01, -0.02};
  EXPECT_EQ(ExactTargetModel(tilted, ExportFormat::kOpenCv)->coeffs, d14);
  EXPECT_EQ(ExactTargetModel(tilted, ExportFormat::kRos)->name, "rational_polynomial");
  EXPECT_EQ(ExactTargetModel(tilted, ExportFormat::kRos)->coeffs, d14);
  EXPECT_FALSE(ExactTargetModel(tilted, ExportFormat::kKalibr));
  EXPECT_FALSE(ExactTargetModel(tilted, ExportFormat::kMrcal));
  CameraModel spline;
  spline.distortion.kind = ModelKind::kBsplineTheta;
  for (ExportFormat f : {ExportFormat::kOpenCv, ExportFormat::kRos, ExportFormat::kKalibr, ExportFormat::kMrcal})
    EXPECT_FALSE(ExactTargetModel(spline, f)) << ExportFormatName(f);
  EXPECT_THROW(ParseExportFormat("colmap"), std::invalid_argument);
}

TEST(LensCircle, EndsWhereTheRadialMapFoldsAndNowhereWhenItRises) {
  CameraModel m;
  m.image_width = 1280, m.image_height = 960;
  m.fx = m.fy = 300, m.cx = 640, m.cy = 480;
  // r (1 + k1 r^2), k1 < 0, rises to (2/3) r_f at r_f = 1 / sqrt(-3 k1), then folds.
  m.distortion = Distortion{ModelKind::kPoly6, 0, {}, {-0.1, 0, 0}};
  const LensCircle folds = FindLensCircle(Camera(m));
  EXPECT_NEAR(folds.radius, 300 * 2.0 / 3.0 / std::sqrt(0.3), 0.05);
  EXPECT_EQ(folds.centre, Eigen::Vector2d(640, 480));
  EXPECT_TRUE(folds.Contains({640 + 360, 480}));
  EXPECT_FALSE(folds.Contains({640 + 370, 480}));
  // An equidistant fisheye rises all the way round to straight back; its
  // calibration's outermost corner (1.2 rad) bounds it, to a quarter degree.
  m.distortion = Distortion{ModelKind::kKb4, 0, {}, {0, 0, 0, 0}};
  EXPECT_TRUE(std::isinf(FindLensCircle(Camera(m)).radius));
  EXPECT_NEAR(FindLensCircle(Camera(m), 1.2).radius, 300 * 1.2, 300 * M_PI / 720);
}

}  // namespace
}  // namespace ws
