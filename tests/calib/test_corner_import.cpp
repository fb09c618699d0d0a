// Corners detected by other tools (BabelCalib's .dsc + .orpc, mrcal's
// corners.vnl) read as views, and each kind of damage named with its line;
// a vnl of two cameras paired by two globs, as mrcal pairs them; and the
// demo rig's corners exported to a vnl and imported back as stereo frames
// calibrating exactly as stereo-detect's own did.
#include <gtest/gtest.h>

#include <fstream>

#include "calib/node/corner_export.h"
#include "calib/node/corner_import.h"
#include "calib/node/glob_captures.h"
#include "calib_process_support.h"
#include "test_support.h"

namespace {

using namespace ws::calib;
using namespace ws::calib::test;

std::string Write(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string path = dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

const char* kTarget =
    "0,3,3,1.0\n"
    "t25h7,2.0\n"
    "-1,0,0,0.75,0.75,0\n"
    "-1,1,0,1.5,0.75,0\n"
    "-1,0,1,0.75,1.5,0\n"
    "7,1,1,1.5,1.5,0\n";

TEST(CornerImport, BabelCalibCornersTakeTheirFiducialsObjectPoints) {
  const std::string dir = ws::test::TempDir("import-babelcalib");
  const std::string dsc = Write(dir, "t.dsc", kTarget);
  const std::string orpc = Write(dir, "a.orpc",
                                 "filename: a.png\nwidth: 640\nheight: 480\nnum_corners: 2\n"
                                 "encoding: ascii\n0,3,1,10.5,20.25\n0,1,1,30,40\n");
  const CameraData data = ReadBabelCalibViews(dsc, {orpc, orpc});
  ASSERT_EQ(data.views.size(), 2u);
  EXPECT_EQ(data.image_width, 640);
  EXPECT_EQ(data.image_height, 480);
  const BoardView& view = data.views[0];
  ASSERT_EQ(view.size(), 2);
  EXPECT_EQ(view.ids, (std::vector<int>{3, 1}));
  EXPECT_EQ(view.object[0], Eigen::Vector3d(1.5, 1.5, 0));
  EXPECT_EQ(view.object[1], Eigen::Vector3d(1.5, 0.75, 0));
  EXPECT_EQ(view.image[0], Eigen::Vector2d(10.5, 20.25));
}

TEST(CornerImport, MrcalCornersAreRowMajorAndDashesAreMissing) {
  const std::string dir = ws::test::TempDir("import-mrcal");
  const std::string vnl = Write(dir, "corners.vnl",
                                "# filename x y level\n"
                                "a.png 1 2 0\na.png - - -\na.png 5 6 0\na.png 7 8 0\n"
                                "b.png - - -\n");
  std::vector<std::string> names;
  const CameraData data = ReadMrcalCorners(vnl, 2, 2, 0.1, 640, 480, &names);
  ASSERT_EQ(data.views.size(), 2u);
  EXPECT_EQ(names, (std::vector<std::string>{"a.png", "b.png"}));
  EXPECT_EQ(data.views[0].ids, (std::vector<int>{0, 2, 3}));
  EXPECT_TRUE(data.views[0].object[2].isApprox(Eigen::Vector3d(0.1, 0.1, 0)));
  EXPECT_EQ(data.views[0].image[1], Eigen::Vector2d(5, 6));
  EXPECT_TRUE(data.views[1].empty());
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void ExpectError(const std::function<void()>& read, const std::string& part) {
  try {
    read();
    FAIL() << "no error, expected one naming '" << part << "'";
  } catch (const CornerImportError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(CornerImport, DamageIsNamedWithFileAndLine) {
  const std::string dir = ws::test::TempDir("import-damage");
  const std::string dsc = Write(dir, "t.dsc", kTarget);
  auto orpc = [&](const std::string& body) {
    return Write(dir, "x.orpc", "width: 640\nheight: 480\n" + body);
  };
  ExpectError([&] { ReadBabelCalibViews(dsc, {orpc("0,9,1,1,2\n")}); }, "x.orpc:3: corner 9");
  ExpectError([&] { ReadBabelCalibViews(dsc, {orpc("0,1,1,nan,2\n")}); }, "x.orpc:3: 'nan'");
  ExpectError([&] { ReadBabelCalibViews(dsc, {orpc("0,1,1,2\n")}); }, "5 comma-separated");
  ExpectError([&] { ReadBabelCalibViews(dsc, {Write(dir, "y.orpc", "0,1,1,1,2\n")}); },
              "no width and height");
  ExpectError([&] { ReadBabelCalibViews(dir + "/absent.dsc", {}); }, "absent.dsc: cannot be read");
  const std::string short_view = Write(dir, "c.vnl", "a.png 1 2 0\nb.png 1 2 0\n");
  ExpectError([&] { ReadMrcalCorners(short_view, 2, 2, 0.1, 640, 480); }, "a.png has 1 corners");
  const std::string bad = Write(dir, "d.vnl", "a.png 1 x 0\n");
  ExpectError([&] { ReadMrcalCorners(bad, 2, 2, 0.1, 640, 480); }, "d.vnl:1: x and y");
  // Corners outside the image (a solve would call such a board collinear).
  ExpectError([&] { ReadBabelCalibViews(dsc, {orpc("0,1,1,99999,2\n")}); }, "x.orpc: corner 1 at (99999");
  const std::string far = Write(dir, "e.vnl", "a.png 1 2 0\na.png 1e308 2 0\na.png 5 6 0\na.png 7 8 0\n");
  ExpectError([&] { ReadMrcalCorners(far, 2, 2, 0.1, 640, 480); }, "e.vnl: a.png: corner 1 at (");
}

TEST(GlobCaptures, EachStarGivesTheTextItMatched) {
  using Captures = std::vector<std::string>;
  EXPECT_EQ(GlobCaptures("*left*", "/data/left-07.png"), Captures({"/data/", "-07.png"}));
  EXPECT_EQ(GlobCaptures("*right*", "/data/right-07.png"), Captures({"/data/", "-07.png"}));
  EXPECT_EQ(GlobCaptures("frame*-cam0.jpg", "frame10-cam0.jpg"), Captures({"10"}));
  EXPECT_EQ(GlobCaptures("a?[0-9][!x]*", "ab7yz"), Captures({"z"}));
  EXPECT_EQ(GlobCaptures("\\*x*", "*x1"), Captures({"1"}));
  EXPECT_EQ(GlobCaptures("no-star.png", "no-star.png"), Captures());
  // Each star takes the shortest text that lets the rest match.
  EXPECT_EQ(GlobCaptures("*-*.png", "a-b-c.png"), Captures({"a", "b-c"}));
  // A relative glob also matches the trailing components of a path (mrcal's rule).
  EXPECT_EQ(GlobCaptures("left-*.png", "/data/set/left-3.png"), Captures({"3"}));
  EXPECT_FALSE(GlobCaptures("/left-*.png", "/data/left-3.png"));
  EXPECT_FALSE(GlobCaptures("left-*.png", "right-3.png"));
  EXPECT_FALSE(GlobCaptures("left-?.png", "left-10.png"));
  EXPECT_EQ(GlobStars("*a[*]\\*b*"), 2);
  EXPECT_THROW(GlobCaptures("left[0-9", "left1"), std::invalid_argument);
}

// A stereo vnl: frames 0 and 2 seen by both cameras, 1 by the right only, 3
// by the left only (its board not found on the right), and a file of
// neither camera.
const char* kStereoVnl =
    "# filename x y level\n"
    "/d/left-0.png 1 2 0\n/d/left-0.png 3 4 0\n/d/left-0.png 5 6 0\n/d/left-0.png 7 8 0\n"
    "/d/right-0.png 11 12 0\n/d/right-0.png 13 14 0\n/d/right-0.png 15 16 0\n/d/right-0.png 17 18 0\n"
    "/d/right-1.png 21 22 0\n/d/right-1.png - - -\n/d/right-1.png 25 26 0\n/d/right-1.png 27 28 0\n"
    "/d/other-1.png 1 1 0\n/d/other-1.png 1 1 0\n/d/other-1.png 1 1 0\n/d/other-1.png 1 1 0\n"
    "/d/right-2.png 31 32 0\n/d/right-2.png 33 34 0\n/d/right-2.png 35 36 0\n/d/right-2.png 37 38 0\n"
    "/d/left-2.png 41 42 0\n/d/left-2.png 43 44 0\n/d/left-2.png 45 46 0\n/d/left-2.png 47 48 0\n"
    "/d/left-3.png 51 52 0\n/d/left-3.png 53 54 0\n/d/left-3.png 55 56 0\n/d/left-3.png 57 58 0\n"
    "/d/right-3.png - - -\n";

TEST(CornerImport, MrcalPairsFollowTheStarsAndOneCameraViewsStay) {
  const std::string dir = ws::test::TempDir("import-pairs");
  const std::string vnl = Write(dir, "corners.vnl", kStereoVnl);
  const PairedViews paired = PairMrcalViews(ReadMrcalViews(vnl, 2, 2, 0.1), "*left*", "*right*", 640, 480);
  const StereoData& data = paired.data;
  ASSERT_EQ(data.size(), 4);
  EXPECT_EQ(paired.unmatched, 1);
  EXPECT_EQ(paired.left_names, (std::vector<std::string>{"/d/left-0.png", "", "/d/left-2.png", "/d/left-3.png"}));
  EXPECT_EQ(paired.right_names,
            (std::vector<std::string>{"/d/right-0.png", "/d/right-1.png", "/d/right-2.png", "/d/right-3.png"}));
  EXPECT_EQ(data.left.views[0].image[3], Eigen::Vector2d(7, 8));
  EXPECT_EQ(data.right.views[0].image[0], Eigen::Vector2d(11, 12));
  EXPECT_TRUE(data.left.views[1].empty());
  EXPECT_EQ(data.right.views[1].ids, (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(data.left.views[2].image[0], Eigen::Vector2d(41, 42));
  EXPECT_EQ(data.right.views[2].image[0], Eigen::Vector2d(31, 32));
  EXPECT_EQ(data.left.views[3].size(), 4);
  EXPECT_TRUE(data.right.views[3].empty());
  for (const CameraData* camera : {&data.left, &data.right}) {
    EXPECT_EQ(camera->image_width, 640);
    EXPECT_EQ(camera->image_height, 480);
  }
  // The same file read as one camera is every image in order.
  EXPECT_EQ(ReadMrcalCorners(vnl, 2, 2, 0.1, 640, 480).views.size(), 8u);
}

TEST(CornerImport, MrcalPairsRefuseGlobsThatCannotNameFrames) {
  const std::string dir = ws::test::TempDir("import-pairs-bad");
  const auto views = ReadMrcalViews(Write(dir, "corners.vnl", kStereoVnl), 2, 2, 0.1);
  ExpectError([&] { PairMrcalViews(views, "*left-*.*", "*right*", 640, 480); }, "as many '*'");
  ExpectError([&] { PairMrcalViews(views, "*-*", "*right*", 640, 480); }, "matches both");
  ExpectError([&] { PairMrcalViews(views, "*left-?.png", "/d/right*", 640, 480); },
              "fall in the same frame");
}

// The demo rig's recorded images (logs/sim-images.lcmlog) detected and
// calibrated, against the same corners written to one corners.vnl and
// imported back with --pairs: the two calibrations are the same.
TEST(StereoImport, DemoRigCornersThroughAVnlCalibrateAsTheImagesDo) {
  const std::string dir = ws::test::TempDir("import-pairs-demo");
  const std::string corners = dir + "/corners.lcmlog";
  const auto detected = ws::test::RunCommand(
      {"stereo-detect", "--board", "chessboard:9x6:0.05", "--log-dir", dir, "--quiet", "--in-url",
       FileUrl(ws::test::SourceDir() + "/logs/sim-images.lcmlog", "speed=0"), "--out-url",
       FileUrl(corners, "mode=w")},
      120);
  ASSERT_EQ(detected.exit_code, 0) << detected.output;
  const StereoData data = ReadCorners(corners);
  std::vector<BoardView> all = data.left.views;
  all.insert(all.end(), data.right.views.begin(), data.right.views.end());
  const BoardLattice lattice = LatticeOf(all);
  {
    std::ofstream vnl(dir + "/corners.vnl");
    WriteMrcalHeader(vnl);
    for (int v = 0; v < data.size(); ++v) {  // right first: the pairing does not lean on order
      WriteMrcalView(vnl, "cam/right/" + std::to_string(v) + ".png", data.right.views[v], lattice);
      WriteMrcalView(vnl, "cam/left/" + std::to_string(v) + ".png", data.left.views[v], lattice);
    }
  }
  const auto imported = ws::test::RunCommand(
      {"stereo-import-corners", "--mrcal", dir + "/corners.vnl", "--board", "chessboard:9x6:0.05",
       "--image-size", std::to_string(data.left.image_width) + "x" + std::to_string(data.left.image_height),
       "--pairs", "*/left/*", "*/right/*", "--log-dir", dir, "--quiet", "--out-url",
       FileUrl(dir + "/imported.lcmlog", "mode=w")},
      60);
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  const StereoData back = ReadCorners(dir + "/imported.lcmlog");
  ASSERT_EQ(back.size(), data.size());
  for (int v = 0; v < data.size(); ++v) {
    EXPECT_EQ(back.left.views[v].image, data.left.views[v].image) << v;
    EXPECT_EQ(back.right.views[v].image, data.right.views[v].image) << v;
    EXPECT_EQ(back.right.views[v].object, data.right.views[v].object) << v;
  }
  for (const auto& [name, log] : {std::pair{"images", corners}, {"vnl", dir + "/imported.lcmlog"}}) {
    const auto run = CalibrateOnce(dir, log, name, {"--model", "bspline"});
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  // The calibration files hold every digit of a double: the same file is
  // the same calibration, not merely one within 1e-9 px.
  EXPECT_EQ(ReadText(dir + "/images.yaml"), ReadText(dir + "/vnl.yaml"));
  EXPECT_EQ(ReadJson(dir + "/images.json")["stereo"]["rms_px"], ReadJson(dir + "/vnl.json")["stereo"]["rms_px"]);
}

}  // namespace
