// Corners detected by other tools (BabelCalib's .dsc + .orpc, mrcal's
// corners.vnl) read as views, and each kind of damage named with its line.
#include <gtest/gtest.h>

#include <fstream>

#include "calib/corner_import.h"
#include "test_support.h"

namespace {

using namespace ws::calib;

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
}

}  // namespace
