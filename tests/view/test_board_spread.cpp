#include "view/board_spread.h"

#include <cmath>

#include <gtest/gtest.h>

namespace {

using ws::view::BoardSpread;
using ws::view::MeasureBoard;

// A 4 x 3 board of 0.1 m squares seen as the parallelogram with corners
// origin, origin + across * 3, origin + down * 2 (+ across * 3).
widestereo::camera_corners_t Board(double ox, double oy, double ax, double ay, double dx, double dy) {
  widestereo::camera_corners_t c{};
  c.image_width = 1000;
  c.image_height = 800;
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 4; ++col) {
      c.ids.push_back(r * 4 + col);
      c.image_points.push_back({ox + col * ax + r * dx, oy + col * ay + r * dy});
      c.object_points.push_back({0.1 * col, 0.1 * r, 0});
    }
  c.n = 12;
  return c;
}

TEST(BoardSpread, MeasuresWhereHowBigAndHowSkewedABoardIs) {
  // An axis-aligned 300 x 300 outline in the top-left corner: x = y = 0, no skew.
  auto m = MeasureBoard(Board(0, 0, 100, 0, 0, 150));
  ASSERT_TRUE(m);
  EXPECT_NEAR((*m)[0], 0, 1e-9);
  EXPECT_NEAR((*m)[1], 0, 1e-9);
  EXPECT_NEAR((*m)[2], std::sqrt(300.0 * 300 / (1000 * 800)), 1e-9);
  EXPECT_NEAR((*m)[3], 0, 1e-9);
  // The same at the bottom-right: x = y = 1.
  m = MeasureBoard(Board(700, 500, 100, 0, 0, 150));
  EXPECT_NEAR((*m)[0], 1, 1e-9);
  EXPECT_NEAR((*m)[1], 1, 1e-9);
  // Sheared by 15 degrees: skew 2 * 15 degrees in radians.
  const double t = std::tan(M_PI / 12);
  m = MeasureBoard(Board(300, 300, 100, 0, 100 * t, 100));
  EXPECT_NEAR((*m)[3], 2 * M_PI / 12, 1e-9);
}

TEST(BoardSpread, RefusesWhatItCannotMeasure) {
  auto c = Board(0, 0, 100, 0, 0, 100);
  c.n = 3;
  EXPECT_FALSE(MeasureBoard(c));
  c = Board(0, 0, 0, 0, 0, 0);  // every corner on one pixel
  EXPECT_FALSE(MeasureBoard(c));
  c = Board(0, 0, 100, 0, 0, 100);
  c.n = 1000;  // more than it carries: only what it carries is read
  EXPECT_TRUE(MeasureBoard(c));
}

TEST(BoardSpread, KeepsOnlyDifferentBoardsAndIsEnoughWhenEveryBarIsFull) {
  BoardSpread spread;
  EXPECT_FALSE(spread.Enough());
  EXPECT_TRUE(spread.Add({0.1, 0.1, 0.3, 0.0}));
  EXPECT_FALSE(spread.Add({0.15, 0.1, 0.3, 0.05})) << "within 0.2 of the first";
  EXPECT_TRUE(spread.Add({0.9, 0.9, 0.5, 0.2}));
  auto p = spread.Progress();
  EXPECT_NEAR(p[0], 0.8 / 0.7 > 1 ? 1 : 0.8 / 0.7, 1e-9);
  EXPECT_NEAR(p[2], 0.2 / 0.4, 1e-9);
  EXPECT_FALSE(spread.Enough());
  EXPECT_TRUE(spread.Add({0.5, 0.5, 0.75, 0.6}));
  EXPECT_TRUE(spread.Enough());
  const auto j = spread.Json();
  EXPECT_EQ(j["boards"], 3);
  EXPECT_EQ(j["bars"][3]["name"], "skew");
  EXPECT_NEAR(j["bars"][3]["high"].get<double>(), 0.6, 1e-12);
  EXPECT_TRUE(j["enough"]);
  spread.Clear();
  EXPECT_FALSE(spread.Enough());
  for (size_t i = 0; i < 2 * BoardSpread::kMaxBoards; ++i) spread.Add({double(i), 0, 0, 0});
  EXPECT_EQ(spread.Json()["boards"], BoardSpread::kMaxBoards) << "bounded";
  spread.Clear();
  EXPECT_TRUE(spread.Json()["bars"][0]["low"].is_null());
}

}  // namespace
