// The calibration file: what the writer puts there reads back bit for bit,
// OpenCV's own cv::FileStorage reads K, R and T, and every damaged field is
// reported with the file, the field and the reason.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <functional>

#include <fstream>
#include <regex>
#include <set>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "calib/node/report.h"
#include "calib/node/solved_rig.h"
#include "models/model_registry.h"
#include "opencv_fisheye.h"
#include "models/camera_field_table.h"
#include "rig/rig_file.h"
#include "runtime/json_file.h"
#include "synthetic_rig.h"
#include "test_support.h"

namespace {

using namespace ws;
using namespace ws::calib;

// A kb4 fisheye: cv::fisheye's model, no tangential terms.
CameraModel Kb4TestCamera(int variant) {
  CameraModel camera = FisheyeTestCamera(variant);
  camera.distortion = Distortion{ModelKind::kKb4, 0, {}, {-0.021 - 0.001 * variant, 0.0043, -0.0029, 4.2e-4}};
  return camera;
}

// The barrel lens's poly6 curve as poly12 (k4 = k5 = k6 = 0).
CameraModel Poly12TestCamera(int variant) {
  CameraModel camera = BarrelTestCamera(variant);
  camera.distortion.kind = ModelKind::kPoly12;
  camera.distortion.coeffs.resize(6, 0.0);
  return camera;
}

CameraModel SampleCamera(ModelKind model, int variant) {
  switch (model) {
    case ModelKind::kBspline: return MustacheTestCamera(variant);
    case ModelKind::kBsplineTheta: return FisheyeTestCamera(variant);
    case ModelKind::kKb4: return Kb4TestCamera(variant);
    case ModelKind::kPoly12: return Poly12TestCamera(variant);
    case ModelKind::kPoly6: break;
  }
  return BarrelTestCamera(variant);
}

Rig SampleRig(ModelKind model) {
  Rig f;
  f.left = SampleCamera(model, 0);
  f.right = SampleCamera(model, 1);
  f.left_rms = 0.1234;
  f.right_rms = 0.2345;
  f.left_views = 30;
  f.right_views = 28;
  f.R = Pose{{0.004, -0.012, 0.003, 0, 0, 0}}.R();
  f.T = {-0.12, 0.0015, 0.002};
  f.rms = 0.1789;
  f.views = 27;
  return f;
}

void Spit(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// What OpenCV reads from a coefficient vector: a cv::Mat, as a list.
std::vector<double> VectorOf(const cv::FileNode& node) {
  cv::Mat mat;
  node >> mat;
  EXPECT_EQ(mat.rows, 1);
  EXPECT_EQ(mat.type(), CV_64F);
  return std::vector<double>(mat.begin<double>(), mat.end<double>());
}

void ExpectSameCamera(const CameraModel& a, const CameraModel& b) {
  EXPECT_EQ(a.image_width, b.image_width);
  EXPECT_EQ(a.image_height, b.image_height);
  EXPECT_EQ(a.Intrinsics(), b.Intrinsics());
  EXPECT_EQ(a.distortion.kind, b.distortion.kind);
  EXPECT_EQ(a.distortion.degree, b.distortion.degree);
  EXPECT_EQ(a.distortion.knots, b.distortion.knots);
  EXPECT_EQ(a.distortion.coeffs, b.distortion.coeffs);
  EXPECT_EQ(a.nonradial.cols, b.nonradial.cols);
  EXPECT_EQ(a.nonradial.rows, b.nonradial.rows);
  EXPECT_EQ(a.nonradial.domain, b.nonradial.domain);
  EXPECT_EQ(a.nonradial.coeffs, b.nonradial.coeffs);
  EXPECT_EQ(a.nonradial.tilt, b.nonradial.tilt);
}

TEST(RigFile, EveryModelReadsBackBitForBit) {
  const std::string dir = test::TempDir("calib-file-roundtrip");
  for (const ModelKind model : ModelKinds()) {
    const Rig written = SampleRig(model);
    const std::string path = dir + "/" + ModelName(model) + ".yaml";
    WriteCalibrationFile(path, written);
    const Rig read = ReadCalibrationFile(path);
    EXPECT_EQ(read.kind(), model);
    ExpectSameCamera(read.left, written.left);
    ExpectSameCamera(read.right, written.right);
    EXPECT_EQ(read.left_rms, written.left_rms);
    EXPECT_EQ(read.right_views, written.right_views);
    EXPECT_EQ(read.R, written.R);
    EXPECT_EQ(read.T, written.T);
    EXPECT_EQ(read.rms, written.rms);
    EXPECT_EQ(read.views, written.views);
  }
}

// A camera with a non-radial field (models/nonradial_field.h) keeps it.
TEST(RigFile, ANonRadialFieldReadsBackBitForBit) {
  const std::string path = test::TempDir("calib-file-field") + "/field.yaml";
  Rig written = SampleRig(ModelKind::kBsplineTheta);
  written.left.nonradial = {5, 4, {-2.1, 2.2, -1.6, 1.5}, std::vector<double>(40)};
  for (size_t k = 0; k < 40; ++k) written.left.nonradial.coeffs[k] = 1e-3 * std::sin(0.3 * k);
  WriteCalibrationFile(path, written);
  const Rig read = ReadCalibrationFile(path);
  ExpectSameCamera(read.left, written.left);
  ExpectSameCamera(read.right, written.right);
  EXPECT_TRUE(read.right.nonradial.empty());
  const Camera a(read.left), b(written.left);
  const Eigen::Vector3d ray(0.3, -0.2, 1.0);
  EXPECT_EQ(*a.Project(ray), *b.Project(ray));
}

// Files written before the coefficient vectors were matrices hold them as
// lists: they load to the same cameras, bit for bit.
TEST(RigFile, FilesWithListsLoadAsBefore) {
  const std::string dir = test::TempDir("calib-file-lists");
  Rig written = SampleRig(ModelKind::kBspline);
  written.left.nonradial = {5, 4, {-2.1, 2.2, -1.6, 1.5}, std::vector<double>(40, 1e-3)};
  WriteCalibrationFile(dir + "/matrices.yaml", written);
  const std::string text = test::ReadFileText(dir + "/matrices.yaml");
  // "KEY: !!opencv-matrix / rows: 1 / cols: N / dt: d / data: [" -> "KEY: ["
  const std::string lists =
      std::regex_replace(text, std::regex(R"(!!opencv-matrix\n +rows: 1\n +cols: \d+\n +dt: d\n +data: \[)"), "[");
  ASSERT_EQ(lists.find("rows: 1\n"), std::string::npos) << lists;
  ASSERT_NE(lists.find("   alpha: [ 0.,"), std::string::npos) << lists;
  Spit(dir + "/lists.yaml", lists);
  const Rig read = ReadCalibrationFile(dir + "/lists.yaml");
  ExpectSameCamera(read.left, written.left);
  ExpectSameCamera(read.right, written.right);
}

// A sensor tilt (models/sensor_tilt.h) alone, and with a field, reads back.
TEST(RigFile, ASensorTiltReadsBackBitForBit) {
  const std::string path = test::TempDir("calib-file-tilt") + "/tilt.yaml";
  Rig written = SampleRig(ModelKind::kKb4);
  written.left.nonradial.tilt = {0.0123, -0.00456};
  written.right.nonradial = {4, 4, {-2.1, 2.2, -1.6, 1.5}, std::vector<double>(32, 1e-3), {-0.002, 0.003}};
  WriteCalibrationFile(path, written);
  const Rig read = ReadCalibrationFile(path);
  ExpectSameCamera(read.left, written.left);
  ExpectSameCamera(read.right, written.right);
  EXPECT_EQ(read.left.nonradial.cols, 0);
}

// The report names a camera's fields as the calibration file does (the one
// table, models/camera_field_table.h; the file holds fx fy cx cy as
// camera_matrix), a model's coefficients under its coeff_key
// (models/model_kind.h), and holds the same numbers under them: a solve's result of every model written both ways as
// stereo-calibrate writes them (calib/node/solved_rig.h's ToRig and the file;
// calib/node/report.h's StereoReport and runtime/json_file.h), then read back.
TEST(RigFile, TheReportNamesEveryModelsCoefficientsAsTheFileDoes) {
  const std::string dir = test::TempDir("rig-file-keys");
  // Every model's sample; bspline_theta's left camera with a field and a tilt.
  auto sample_of = [](ModelKind model) {
    Rig sample = SampleRig(model);
    if (model == ModelKind::kBsplineTheta)
      sample.left.nonradial = NonRadial{4, 4, {-1.5, 1.5, -1, 1}, std::vector<double>(32, 1e-4), {0.01, -0.02}};
    return sample;
  };
  std::set<std::string> keys;
  for (const ModelKind model : ModelKinds())
    ForEachCameraField(sample_of(model).left, [&](const std::string& key, const auto&) {
      if (key != "fx" && key != "fy" && key != "cx" && key != "cy") keys.insert(key);
    });
  ASSERT_TRUE(keys.count("nonradial") && keys.count("knots") && keys.count("alpha") && keys.count("k"));
  for (const ModelKind model : ModelKinds()) {
    const Rig sample = sample_of(model);
    StereoCalibration result;
    result.model = model;
    result.left.name = "left";
    result.left.model = sample.left;
    result.right.name = "right";
    result.right.model = sample.right;
    result.R = sample.R;
    result.T = sample.T;
    const std::string yaml = dir + "/" + ModelName(model) + ".yaml";
    const std::string json = dir + "/" + ModelName(model) + ".json";
    WriteCalibrationFile(yaml, ToRig(result));
    WriteJsonFile(json, StereoReport(result));

    const Rig read = ReadCalibrationFile(yaml);
    cv::FileStorage file(yaml, cv::FileStorage::READ);
    const nlohmann::json report = nlohmann::json::parse(test::ReadFileText(json));
    EXPECT_EQ(report["model"], static_cast<std::string>(file["model"])) << model;
    ASSERT_EQ(report["cameras"].size(), 2u) << model;
    for (int c = 0; c < 2; ++c) {
      const nlohmann::json& in_report = report["cameras"][c];
      const std::string name = in_report["name"].get<std::string>();
      const cv::FileNode in_file = file[name];
      const CameraModel& camera = c == 0 ? read.left : read.right;
      const std::string at = ModelName(model) + " " + name;
      EXPECT_EQ(in_report["model"], static_cast<std::string>(in_file["model"])) << at;
      for (const std::string& key : keys)
        EXPECT_EQ(!in_file[key].empty(), in_report.contains(key)) << at << ": " << key;
      if (in_report.contains("nonradial")) {
        for (const char* key : {"cols", "rows", "domain", "coeffs", "tilt"})
          EXPECT_EQ(!in_file["nonradial"][key].empty(), in_report["nonradial"].contains(key)) << at << ": " << key;
      }
      const std::string key = Traits(model).coeff_key;
      ASSERT_TRUE(in_report.contains(key)) << at;
      const std::vector<double> coeffs = VectorOf(in_file[key]);
      EXPECT_EQ(in_report[key].get<std::vector<double>>(), coeffs) << at;
      EXPECT_EQ(coeffs, camera.distortion.coeffs) << at;
      EXPECT_EQ(in_report.value("knots", std::vector<double>{}), camera.distortion.knots) << at;
      EXPECT_EQ(in_report["degree"].get<int>(), static_cast<int>(in_file["degree"])) << at;
    }
  }
}

TEST(RigFile, OpenCvReadsTheMatricesDirectly) {
  const std::string path = test::TempDir("calib-file-opencv") + "/calib.yaml";
  const Rig f = SampleRig(ModelKind::kBspline);
  WriteCalibrationFile(path, f);
  cv::FileStorage fs(path, cv::FileStorage::READ);
  ASSERT_TRUE(fs.isOpened());
  cv::Mat K, R, T;
  fs["left"]["camera_matrix"] >> K;
  fs["stereo"]["R"] >> R;
  fs["stereo"]["T"] >> T;
  ASSERT_EQ(K.size(), cv::Size(3, 3));
  EXPECT_EQ(K.at<double>(0, 0), f.left.fx);
  EXPECT_EQ(K.at<double>(1, 2), f.left.cy);
  EXPECT_EQ(R.at<double>(0, 2), f.R(0, 2));
  EXPECT_EQ(T.at<double>(0), f.T.x());
  EXPECT_EQ(VectorOf(fs["right"]["alpha"]), f.right.distortion.coeffs);
  EXPECT_EQ(static_cast<std::string>(fs["right"]["model"]), "bspline");
  EXPECT_EQ(static_cast<double>(fs["stereo"]["baseline_m"]), f.T.norm());
}

// A kb4 file is cv::fisheye's K and D: OpenCV projects with them exactly as
// the file's model does, rays beyond OpenCV's 90 degrees aside.
TEST(RigFile, Kb4LoadsIntoOpenCvFisheye) {
  const std::string path = test::TempDir("calib-file-kb4") + "/kb4.yaml";
  const Rig f = SampleRig(ModelKind::kKb4);
  WriteCalibrationFile(path, f);
  cv::FileStorage fs(path, cv::FileStorage::READ);
  ASSERT_TRUE(fs.isOpened());
  cv::Mat K, D;
  fs["left"]["camera_matrix"] >> K;
  fs["left"]["k"] >> D;  // docs/models.md
  ASSERT_EQ(D.total(), 4u);
  std::vector<cv::Point3d> points;
  for (double deg = 0; deg < 89; deg += 4)
    for (double phi = 0; phi < 6.28; phi += 0.7)
      points.emplace_back(std::sin(deg * M_PI / 180) * std::cos(phi),
                          std::sin(deg * M_PI / 180) * std::sin(phi), std::cos(deg * M_PI / 180));
  EXPECT_LT(test::WorstGapToOpenCvFisheye(Camera(ReadCalibrationFile(path).left), points, K, D),
            1e-9);
}

// A valid file's text with `from` replaced by `to` must fail naming `field`.
struct Damage {
  std::string from, to, field, reason;
};

TEST(RigFile, EachDamagedFieldIsNamed) {
  const std::string dir = test::TempDir("calib-file-damage");
  const std::string good = dir + "/good.yaml";
  WriteCalibrationFile(good, SampleRig(ModelKind::kBspline));
  const std::string text = test::ReadFileText(good);
  ASSERT_NO_THROW(ReadCalibrationFile(good));
  std::vector<Damage> damages = {
      {"left:\n   image_width: 1280", "left:\n   image_widht: 1280", "left.image_width", "missing"},
      {"image_height: 960", "image_height: -960", "left.image_height", "below 1"},
      {"image_height: 960", "image_height: 960.5", "left.image_height", "not an integer"},
      {"rows: 3\n      cols: 3", "rows: 1\n      cols: 9", "left.camera_matrix", "3x3"},
      // Refused before OpenCV allocates the 48 GB it claims (a fuzz finding).
      {"rows: 3\n      cols: 3", "rows: 2000000000\n      cols: 3", "left.camera_matrix", "3x3"},
      {"   model: bspline\n", "   model: fisheye\n", "left.model", "unknown model"},
      {"   degree: 3\n", "   degree: 0\n", "left.degree", "below 1"},
      {"cols: 39\n      dt: d\n      data: [ 0., 0., 0., 0.,", "cols: 39\n      dt: d\n      data: [ 0., 0., 0., 1.,",
       "left.knots", "must not decrease"},
      {"cols: 35\n      dt: d\n      data: [ 0.,", "cols: 35\n      dt: d\n      data: [ .Nan,", "left.alpha[0]",
       "not finite"},
      {"cols: 35\n      dt: d\n      data: [ 0.,", "cols: 34\n      dt: d\n      data: [", "left.alpha",
       "coefficients"},
      {"cols: 35\n      dt: d\n", "cols: 36\n      dt: d\n", "left.alpha", "not a 1 x N !!opencv-matrix"},
      {"cols: 35\n      dt: d\n", "cols: 35\n      dt: u\n", "left.alpha", "not a 1 x N !!opencv-matrix"},
      {"rows: 1\n      cols: 35\n", "rows: 2\n      cols: 35\n", "left.alpha", "not a 1 x N !!opencv-matrix"},
      // Refused from the size it claims, before its numbers are read.
      {"cols: 35\n      dt: d\n", "cols: 2000000000\n      dt: d\n", "left.alpha", "more than 512 numbers"},
      {"   p1: ", "   p1: abc\n   p1_was: ", "left.p1", "not a number"},
      {"   rms: 1.234", "   rms: -1.234", "left.rms", "negative"},
      {"right:", "rigth:", "right", "missing"},
      {"stereo:", "stereo_:", "stereo", "missing"},
      {"baseline_m: ", "baseline_m: 3.0\n   was: ", "stereo.baseline_m", "differs from |T|"},
      {"model: bspline\nleft:", "model: poly6\nleft:", "model", "a camera's model is 'bspline'"},
  };
  // A knot list far longer than any lens needs is refused before it is read
  // (it was read in quadratic time: 10^7 knots hung the loader).
  const std::string knots = "   knots: !!opencv-matrix\n      rows: 1\n      cols: 39\n      dt: d\n      data: [";
  std::string many_knots = "   knots: [";
  for (int i = 0; i < 100000; ++i) many_knots += " 0.5,";
  damages.push_back({knots, many_knots, "left.knots", "more than 512 numbers"});
  for (const Damage& d : damages) {
    const size_t at = text.find(d.from);
    ASSERT_NE(at, std::string::npos) << d.from;
    std::string damaged = text;
    damaged.replace(at, d.from.size(), d.to);
    const std::string path = dir + "/damaged.yaml";
    Spit(path, damaged);
    try {
      ReadCalibrationFile(path);
      ADD_FAILURE() << "accepted a file with " << d.to;
    } catch (const CalibrationFileError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(path + ": " + d.field + ": "), std::string::npos) << message;
      EXPECT_NE(message.find(d.reason), std::string::npos) << message;
    }
  }
}

// The ranges a STEREO_CALIBRATION message must keep hold for a file too
// (once fx = 1e-300 and 1e308 loaded, and stereo-match ran with f = 0 px).
TEST(RigFile, RefusesValuesNoCameraHasAsItsMessageDoes) {
  const std::string path = test::TempDir("calib-file-ranges") + "/calib.yaml";
  const std::vector<std::pair<std::function<void(Rig&)>, std::string>> absurd = {
      {[](Rig& f) { f.left.fx = 1e-300; }, "left: fx and fy must be in"},
      {[](Rig& f) { f.right.fy = 1e308; }, "right: fx and fy must be in"},
      {[](Rig& f) { f.left.distortion.coeffs.back() = 1e300; }, "a distortion coefficient beyond 1e8"},
      {[](Rig& f) { f.T.setZero(); }, "stereo.T: a zero baseline"},
  };
  for (const auto& [spoil, says] : absurd) {
    Rig f = SampleRig(ModelKind::kPoly6);
    spoil(f);
    WriteCalibrationFile(path, f);
    try {
      ReadCalibrationFile(path);
      ADD_FAILURE() << "accepted: " << says;
    } catch (const CalibrationFileError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

// A FIFO, a device or a folder is refused before it is read (a FIFO
// blocked the reader; /dev/zero was read for 2 GB).
TEST(RigFile, RefusesWhatIsNoRegularFileBeforeReadingIt) {
  const std::string dir = test::TempDir("calib-file-fifo");
  ASSERT_EQ(mkfifo((dir + "/fifo.yaml").c_str(), 0644), 0);
  for (const std::string& path : {dir + "/fifo.yaml", std::string("/dev/zero"), dir}) {
    try {
      ReadCalibrationFile(path);
      ADD_FAILURE() << "accepted " << path;
    } catch (const CalibrationFileError& e) {
      EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
    }
  }
}

TEST(RigFile, RejectsARotationThatIsNot) {
  const std::string path = test::TempDir("calib-file-rotation") + "/calib.yaml";
  Rig f = SampleRig(ModelKind::kPoly6);
  f.R(0, 0) *= 1.01;
  WriteCalibrationFile(path, f);
  try {
    ReadCalibrationFile(path);
    FAIL() << "accepted a stretched R";
  } catch (const CalibrationFileError& e) {
    EXPECT_NE(std::string(e.what()).find(": stereo.R: not a rotation"), std::string::npos)
        << e.what();
  }
}

TEST(RigFile, MissingOrNonYamlFilesSayWhich) {
  const std::string dir = test::TempDir("calib-file-missing");
  EXPECT_THROW(ReadCalibrationFile(dir + "/none.yaml"), CalibrationFileError);
  Spit(dir + "/garbage.yaml", "%YAML:1.0\n---\nleft: [ unclosed\n");
  try {
    ReadCalibrationFile(dir + "/garbage.yaml");
    FAIL() << "accepted garbage";
  } catch (const CalibrationFileError& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/garbage.yaml: "), std::string::npos) << e.what();
  }
}

}  // namespace
