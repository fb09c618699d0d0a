// fuzz-seeds OUT: writes the seed corpus of every fuzz target to OUT/<target>/
// from real data: OpenCV's stereo calibration images (Debian opencv-doc) in
// every pixel format and compression, the corners stereo-detect finds in
// them, calibrations of the simulator's cameras, the repository's config
// files, PCD files in each of PCL's encodings and an LCM log of real messages.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include "auth/message_auth.h"
#include "cloud/pcd_io.h"
#include "detect/stereo_corner_finder.h"
#include "fuzz_support.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "rig/rig_message.h"
#include "sim/sim_config.h"
#include "widestereo/calibration_health_t.hpp"
#include "widestereo/calibration_result_t.hpp"
#include "widestereo/calibration_views_t.hpp"
#include "widestereo/calibration_status_t.hpp"
#include "widestereo/cloud_stats_t.hpp"
#include "widestereo/command_t.hpp"
#include "widestereo/disparity_t.hpp"
#include "widestereo/point_cloud_t.hpp"
#include "widestereo/process_status_t.hpp"
#include "widestereo/stereo_calibration_t.hpp"

namespace {

namespace fs = std::filesystem;
using namespace widestereo;

const std::string kOpenCvData = "/usr/share/doc/opencv-doc/examples/data/";

class Seeds {
 public:
  explicit Seeds(fs::path root) : root_(std::move(root)) {}

  void Bytes(const std::string& target, const std::string& name, const std::vector<uint8_t>& bytes) {
    fs::create_directories(root_ / target);
    std::ofstream out(root_ / target / name, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    ++count_;
  }
  template <class Msg>
  void Message(const std::string& name, const Msg& msg) {
    Bytes(std::string("fuzz_") + Msg::getTypeName(), name, Encode(msg));
  }
  void Copy(const std::string& target, const fs::path& file) {
    fs::create_directories(root_ / target);
    fs::copy_file(file, root_ / target / file.filename(), fs::copy_options::overwrite_existing);
    ++count_;
  }
  fs::path Path(const std::string& target, const std::string& name) {
    fs::create_directories(root_ / target);
    ++count_;
    return root_ / target / name;
  }
  int count() const { return count_; }

  template <class Msg>
  static std::vector<uint8_t> Encode(const Msg& msg) {
    std::vector<uint8_t> bytes(size_t(msg.getEncodedSize()));
    msg.encode(bytes.data(), 0, int(bytes.size()));
    return bytes;
  }

 private:
  fs::path root_;
  int count_ = 0;
};

cv::Mat Small(const std::string& file, int flags = cv::IMREAD_COLOR) {
  const cv::Mat image = cv::imread(kOpenCvData + file, flags);
  if (image.empty()) throw std::runtime_error("cannot read " + kOpenCvData + file);
  cv::Mat small;
  cv::resize(image, small, {32, 24}, 0, 0, cv::INTER_AREA);
  return small;
}

void ImageSeeds(Seeds& seeds) {
  const cv::Mat bgr = Small("left01.jpg"), gray = Small("left01.jpg", cv::IMREAD_GRAYSCALE);
  cv::Mat gray16, real, bgra;
  gray.convertTo(gray16, CV_16U, 257);
  gray.convertTo(real, CV_32F, 1 / 255.0);
  cv::cvtColor(bgr, bgra, cv::COLOR_BGR2BGRA);
  seeds.Message("gray", ws::MatToImage(gray, 1));
  seeds.Message("gray16", ws::MatToImage(gray16, 1));
  seeds.Message("bgr", ws::MatToImage(bgr, 1));
  image_t rgb = ws::MatToImage(bgr, 1);
  rgb.pixelformat = image_t::PIXEL_FORMAT_RGB;
  seeds.Message("rgb", rgb);
  seeds.Message("float", ws::MatToImage(real, 1));
  seeds.Message("gray.jpg", ws::MatToImage(gray, 1, ws::Compression::jpeg, 80));
  seeds.Message("bgr.jpg", ws::MatToImage(bgr, 1, ws::Compression::jpeg, 80));
  seeds.Message("gray.png", ws::MatToImage(gray, 1, ws::Compression::png));
  seeds.Message("gray16.png", ws::MatToImage(gray16, 1, ws::Compression::png));
  seeds.Message("bgra.png", ws::MatToImage(bgra, 1, ws::Compression::png));
  // Rows padded to 36 bytes, and a key/value metadata entry.
  image_t padded = ws::MatToImage(gray, 1);
  padded.row_stride = 36;
  padded.data.assign(size_t(36) * 24, 0);
  for (int y = 0; y < 24; ++y) std::copy(gray.ptr(y), gray.ptr(y) + 32, padded.data.begin() + 36 * y);
  padded.size = int32_t(padded.data.size());
  padded.metadata.push_back({"exposure_us", 5, {'1', '0', '0', '0', '0'}});
  padded.nmetadata = 1;
  seeds.Message("padded-with-metadata", padded);

  disparity_t disparity{};
  disparity.utime = disparity.frame_id = 1;
  disparity.disparity = ws::MatToImage(real * 64, 1);
  disparity.num_disparities = 64;
  for (int i = 0; i < 16; ++i) disparity.Q[i] = i % 5 == 0;
  disparity.rectification = disparity_t::RECTIFICATION_PINHOLE;
  disparity.f = 300;
  disparity.cx = 320;
  disparity.cy = 240;
  disparity.baseline = 0.12;
  seeds.Message("disparity", disparity);
}

stereo_frame_t Frame(const std::string& pair, ws::Compression compression, cv::Size size) {
  stereo_frame_t frame{};
  frame.utime = frame.frame_id = 1;
  for (auto [side, image] : {std::pair{"left", &frame.left}, std::pair{"right", &frame.right}}) {
    cv::Mat gray = cv::imread(kOpenCvData + side + pair + ".jpg", cv::IMREAD_GRAYSCALE);
    if (gray.size() != size) cv::resize(gray, gray, size, 0, 0, cv::INTER_AREA);
    *image = ws::MatToImage(gray, 1, compression, 80);
  }
  return frame;
}

void FrameAndCornerSeeds(Seeds& seeds, std::vector<stereo_frame_t>* log_frames,
                         std::vector<stereo_corners_t>* log_corners) {
  const cv::Size small(32, 24);
  seeds.Message("gray", Frame("01", ws::Compression::none, small));
  seeds.Message("jpeg", Frame("01", ws::Compression::jpeg, small));
  seeds.Message("png", Frame("01", ws::Compression::png, small));
  stereo_frame_t mono = Frame("01", ws::Compression::none, small);  // stereo-capture --mono's
  mono.right = ws::NoImage(mono.utime);
  seeds.Message("mono", mono);
  stereo_frame_t signed_frame = Frame("01", ws::Compression::jpeg, small);
  ws::auth::Sign(ws::fuzz::FuzzKey(), ws::channel::kStereoImages, "stereo-capture@robot pid 42", 1000000, signed_frame);
  seeds.Message("signed-jpeg", signed_frame);
  log_frames->push_back(Frame("01", ws::Compression::none, {16, 12}));

  const ws::StereoCornerFinder finder(ws::ParseBoardSpec("chessboard:9x6:0.025"),
                                      ws::ChessboardMethod::classic);
  for (const char* pair : {"01", "02"}) {
    const stereo_corners_t corners = finder.Find(Frame(pair, ws::Compression::none, {640, 480}));
    if (corners.left.n == 0 || corners.right.n == 0)
      throw std::runtime_error(std::string("no corners found in pair ") + pair);
    seeds.Message(std::string("pair") + pair, corners);
    stereo_corners_t signed_corners = corners;
    ws::auth::Sign(ws::fuzz::FuzzKey(), ws::channel::kStereoCorners, "stereo-detect@robot pid 42", 1000000,
                   signed_corners);
    seeds.Message(std::string("signed-pair") + pair, signed_corners);
    seeds.Message(std::string("left") + pair, corners.left);
    log_corners->push_back(corners);
  }
  camera_corners_t none{};
  none.board_id = "chessboard:9x6:0.025";
  seeds.Message("no-board", none);
}

void CalibrationSeeds(Seeds& seeds) {
  const ws::SimConfig sim = ws::DefaultSimConfig(0.1);
  ws::Rig rig;
  rig.left = rig.right = sim.left;
  rig.T = Eigen::Vector3d(-0.3, 0, 0);
  seeds.Message("bspline", ws::MessageFromRig(rig, 1));
  rig.left.distortion = rig.right.distortion = ws::Distortion{ws::ModelKind::kPoly6, 0, {}, {-0.2, 0.05, -0.004}};
  stereo_calibration_t poly6 = ws::MessageFromRig(rig, 1);
  // With the quality figures a solver fills in.
  poly6.rms = 0.06;
  poly6.left.nviews = 2;
  poly6.left.view_rms = {0.04, 0.06};
  poly6.left.nparams = 2;
  poly6.left.param_names = {"fx", "fy"};
  poly6.left.stddev = {0.1, 0.1};
  seeds.Message("poly6", poly6);
  ws::auth::Sign(ws::fuzz::FuzzKey(), ws::channel::kStereoCalibration, "stereo-calibrate@robot pid 42", 1000000, poly6);
  seeds.Message("signed-poly6", poly6);
  seeds.Message("bspline", ws::MessageFromCameraModel(sim.left, "left"));
  seeds.Message("poly6", poly6.left);
  // A fisheye model with a non-radial field and a sensor tilt.
  ws::CameraModel field = ws::DefaultSimConfig(0.1).left;
  field.nonradial = {4, 4, {-1.5, 1.5, -1.2, 1.2}, std::vector<double>(32, 0.0), {0.004, -0.003}};
  for (size_t k = 0; k < field.nonradial.coeffs.size(); ++k) field.nonradial.coeffs[k] = 1e-3 * (k % 5);
  rig.left = rig.right = field;
  seeds.Message("bspline-field", ws::MessageFromRig(rig, 1));
  seeds.Message("bspline-field", ws::MessageFromCameraModel(field, "left"));
}

process_status_t StatusMessage() {
  process_status_t status{};
  status.utime = 1000000;
  status.name = "stereo-detect";
  status.host = "robot";
  status.pid = 42;
  status.uptime_s = 12.5;
  status.state = "running";
  for (const char* channel : {ws::channel::kStereoImages, ws::channel::kStereoCorners})
    status.channels.push_back({channel, 120, 118, 1, 2, 1});
  status.nchannels = 2;
  status.last_error = "STEREO_IMAGES: image_t: bad image size 0x0";
  status.stages = {{"receive STEREO_IMAGES", 120, 120, 1.5f, 3.0f}, {"detect", 118, 118, 40.f, 75.f}};
  status.nstages = 2;
  return status;
}

void StatusAndCommandSeeds(Seeds& seeds) {
  seeds.Message("detect", StatusMessage());
  calibration_status_t calibration{};
  calibration.utime = 1;
  calibration.state = "collecting";
  calibration.views_left = calibration.views_right = calibration.views_stereo = 5;
  calibration.grid_rows = 3;
  calibration.grid_cols = 4;
  calibration.coverage_left = calibration.coverage_right = {{1, 2, 3, 4}, {0, 0, 9, 1}, {5, 5, 0, 0}};
  calibration.rms = 0.3;
  calibration.heldout_rms = 0.35;
  calibration.hint = "move the board to the top left";
  seeds.Message("collecting", calibration);
  calibration_health_t health{};
  health.utime = 1;
  health.frame_id = 7;
  health.verdict = "misaligned";
  health.max_dy_px = 0.3;
  health.dy_median_px = 1.2;
  health.dy_p95_px = 2.8;
  health.matches = 960;
  health.frames = 3;
  health.grid_rows = 3;
  health.grid_cols = 4;
  health.grid_dy_px = {{-1.5, -0.5, 0.5, 1.5}, {-1.4, -0.4, 0.4, 1.4}, {-1.5, -0.5, 0.5, 1.5}};
  health.grid_matches = {{20, 100, 130, 30}, {30, 150, 140, 70}, {10, 100, 120, 30}};
  health.calibration = "calibration file config/calib/sim-default.yaml";
  seeds.Message("misaligned", health);
  health.verdict = "unknown";
  health.dy_median_px = health.dy_p95_px = -1;
  health.matches = health.frames = health.grid_rows = health.grid_cols = 0;
  health.grid_dy_px.clear();
  health.grid_matches.clear();
  seeds.Message("unknown-no-grid", health);
  calibration_result_t result{};
  result.utime = 1;
  result.chosen = "bspline";
  result.models = {{"bspline", "", 0.1, 0.11, 0.12, 0.13, 0.12}, {"poly12", "did not converge", -1, -1, -1, -1, -1}};
  result.nmodels = 2;
  camera_maps_t maps{};
  maps.name = "left";
  maps.image_width = 640;
  maps.image_height = 480;
  maps.residual_rows = 2;
  maps.residual_cols = 3;
  maps.residual_rms_px = {{0.1, -1, 0.2}, {0.3, 0.1, -1}};
  maps.uncertainty_rows = 1;
  maps.uncertainty_cols = 2;
  maps.uncertainty_px = {{0.05, 0.4}};
  result.cameras = {maps, maps};
  result.cameras[1].name = "right";
  result.ncameras = 2;
  seeds.Message("two-models", result);
  calibration_views_t views{};
  views.utime = 2;
  views.solve_utime = 1;
  views.image_width[0] = views.image_width[1] = 1280;
  views.image_height[0] = views.image_height[1] = 960;
  calibration_view_t view{};
  view.frame_id = 7;
  view.frame_utime = 700000;
  view.left_corners = view.right_corners = 54;
  view.left_outline[1][0] = view.right_outline[2][1] = 400;
  view.left_rms = 0.12;
  view.right_rms = -1;
  views.views = {view, view};
  views.views[1].frame_id = 9;
  views.nviews = 2;
  seeds.Message("two-views", views);
  command_t command{};
  command.command = "solve";
  command.target = "stereo-calibrate";
  command.args = {"model=bspline", "path=calib2.yaml"};
  command.nargs = 2;
  seeds.Message("solve", command);
  ws::auth::Sign(ws::fuzz::FuzzKey(), ws::channel::kStereoCommand, "stereo-command@robot pid 42", 1000000, command);
  seeds.Message("signed-solve", command);
  cloud_stats_t stats{};
  stats.plane_found = true;
  stats.plane_normal[2] = -1;
  stats.plane_offset = 2;
  stats.stage_names = {"input", "passthrough", "voxel", "outliers", "plane"};
  stats.stage_points = {100, 90, 60, 55, 40};
  stats.stage_ms = {0, 0.1, 0.5, 0.7, 1.2};
  stats.nstages = 5;
  seeds.Message("five-stages", stats);
}

ws::PointCloud Cloud(bool with_intensity) {
  ws::PointCloud cloud;
  cloud.frame = "left_rectified";
  for (int i = 0; i < 40; ++i) {
    cloud.xyz.push_back({0.05f * (i % 8), 0.05f * float(i / 8), 2.0f + 0.001f * float(i % 3)});
    if (with_intensity) cloud.intensity.push_back(float(i * 6));
  }
  cloud.npoints = int32_t(cloud.xyz.size());
  cloud.nintensity = int32_t(cloud.intensity.size());
  return cloud;
}

void CloudSeeds(Seeds& seeds) {
  seeds.Message("with-intensity", Cloud(true));
  seeds.Message("xyz", Cloud(false));
  ws::WritePcd(seeds.Path("fuzz_pcd", "binary-xyzi.pcd").string(), Cloud(true));
  ws::WritePcd(seeds.Path("fuzz_pcd", "binary-xyz.pcd").string(), Cloud(false));
  pcl::PointCloud<pcl::PointXYZ> pcl_cloud;
  for (const auto& p : Cloud(false).xyz) pcl_cloud.push_back({p[0], p[1], p[2]});
  pcl::io::savePCDFileASCII(seeds.Path("fuzz_pcd", "ascii.pcd").string(), pcl_cloud);
  pcl::io::savePCDFileBinaryCompressed(seeds.Path("fuzz_pcd", "compressed.pcd").string(), pcl_cloud);
}

// A log of real messages, and the same cut in the middle of its last event.
void LogSeeds(Seeds& seeds, const std::vector<stereo_frame_t>& frames,
              const std::vector<stereo_corners_t>& corners) {
  const fs::path path = seeds.Path("fuzz_lcm_log", "pipeline.lcmlog");
  {
    lcm::LogFile log(path.string(), "w");
    int64_t n = 0;
    auto write = [&](const std::string& channel, const std::vector<uint8_t>& bytes) {
      lcm::LogEvent event{n, 1000000 * (n + 1), channel, int32_t(bytes.size()),
                          const_cast<uint8_t*>(bytes.data())};
      ++n;
      log.writeEvent(&event);
    };
    write(ws::channel::kProcessStatus, Seeds::Encode(StatusMessage()));
    for (const auto& frame : frames) write(ws::channel::kStereoImages, Seeds::Encode(frame));
    write(ws::channel::kStereoCorners, Seeds::Encode(corners.front()));
  }
  const fs::path cut = seeds.Path("fuzz_lcm_log", "cut.lcmlog");
  fs::copy_file(path, cut, fs::copy_options::overwrite_existing);
  fs::resize_file(cut, fs::file_size(cut) - 100);
  // One byte flipped in the second event's sync word: the recovery's path.
  const fs::path flipped = seeds.Path("fuzz_lcm_log", "flipped.lcmlog");
  fs::copy_file(path, flipped, fs::copy_options::overwrite_existing);
  const int64_t second = 4 + 8 + 8 + 4 + 4 + int64_t(std::string(ws::channel::kProcessStatus).size()) +
                         int64_t(Seeds::Encode(StatusMessage()).size());
  std::fstream file(flipped, std::ios::in | std::ios::out | std::ios::binary);
  file.seekp(second);
  file.put('\x00');
}

void ConfigSeeds(Seeds& seeds, const fs::path& source) {
  for (const char* process :
       {"stereo-capture", "stereo-detect", "stereo-match", "stereo-calibrate", "stereo-cloud", "stereo-health"})
    seeds.Copy("fuzz_yaml_config", source / "config" / (std::string(process) + ".yaml"));
  for (const auto& entry : fs::directory_iterator(source / "config" / "sim"))
    seeds.Copy("fuzz_sim_config", entry.path());
  for (const auto& entry : fs::directory_iterator(source / "config" / "rig"))
    seeds.Copy("fuzz_rig_config", entry.path());
  for (const auto& entry : fs::directory_iterator(source / "config" / "calib"))
    seeds.Copy("fuzz_calib_file", entry.path());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]) == "--help") {
    std::printf("usage: fuzz-seeds OUT\nWrites the seed corpus of every fuzz target to OUT/<target>/.\n");
    return argc == 2 ? 0 : 2;
  }
  try {
    Seeds seeds{fs::path(argv[1])};
    std::vector<stereo_frame_t> frames;
    std::vector<stereo_corners_t> corners;
    ImageSeeds(seeds);
    FrameAndCornerSeeds(seeds, &frames, &corners);
    CalibrationSeeds(seeds);
    StatusAndCommandSeeds(seeds);
    CloudSeeds(seeds);
    LogSeeds(seeds, frames, corners);
    ConfigSeeds(seeds, WS_SOURCE_DIR);
    std::printf("fuzz-seeds: %d seeds in %s\n", seeds.count(), argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz-seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
