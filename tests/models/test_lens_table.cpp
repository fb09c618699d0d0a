#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "models/lens_table.h"
#include "models/theia_lens.h"

namespace ws {
namespace {

LensTable Parse(const std::string& text, TableColumns columns = TableColumns::kRealHeight) {
  std::istringstream in(text);
  return ParseLensTable(in, "t.csv", columns);
}

// The LensTableError message of parsing `text`, or "" if it parsed.
std::string ErrorOf(const std::string& text, TableColumns columns = TableColumns::kRealHeight) {
  try {
    Parse(text, columns);
  } catch (const LensTableError& error) {
    return error.what();
  }
  return "";
}

TEST(LensTable, ParsesHeightsSkippingCommentsBlankLinesAndCarriageReturns) {
  const LensTable table = Parse("# a lens\nideal_mm, real_mm\r\n0,0\r\n\n0.5, 0.51\n1.0,1.01\n");
  EXPECT_EQ(table.ideal, (std::vector<double>{0, 0.5, 1.0}));
  EXPECT_EQ(table.real, (std::vector<double>{0, 0.51, 1.01}));
}

TEST(LensTable, ConvertsPercentDistortionToHeights) {
  const LensTable table = Parse("h,percent\n0,0\n1,2\n2,-1.5\n", TableColumns::kPercent);
  EXPECT_EQ(table.real[0], 0.0);
  EXPECT_DOUBLE_EQ(table.real[1], 1.02);
  EXPECT_DOUBLE_EQ(table.real[2], 2 * 0.985);
}

TEST(LensTable, ReportsFileLineAndReason) {
  EXPECT_EQ(ErrorOf("0,0\n1,1\n2,2\n"),
            "t.csv:1: expected a header line (column names) before the numbers");
  EXPECT_EQ(ErrorOf("h,r\n0,0\n1,1,1\n2,2\n"), "t.csv:3: expected 2 comma-separated columns, found 3");
  EXPECT_EQ(ErrorOf("h,r\n0,0\n1,x\n2,2\n"), "t.csv:3: real height 'x' is not a number");
  EXPECT_EQ(ErrorOf("h,r\n0,0\n1,\n2,2\n"), "t.csv:3: real height '' is not a number");
  EXPECT_EQ(ErrorOf("h,r\n0,0\n1e999,1\n2,2\n"), "t.csv:3: ideal height '1e999' is not a number");
  EXPECT_EQ(ErrorOf("h,r\n0,0\n1,1\n1,1.1\n"),
            "t.csv:4: ideal height 1 is not greater than 1 on the previous row");
  EXPECT_EQ(ErrorOf("h,r\n0,0\n1,1\n2,0.9\n"),
            "t.csv:4: real height 0.9 is not greater than 1 on the previous row (r' must increase "
            "with r)");
  EXPECT_EQ(ErrorOf("h,r\n0,0.1\n1,1\n2,2\n"),
            "t.csv:2: real height 0.1 at ideal height 0 (must be 0 on the axis)");
  EXPECT_EQ(ErrorOf("h,r\n-1,0\n1,1\n2,2\n"), "t.csv:2: ideal height -1 is negative");
  EXPECT_EQ(ErrorOf("h,r\n0.5,-0.1\n1,1\n2,2\n"), "t.csv:2: real height -0.1 is not positive");
  EXPECT_EQ(ErrorOf("h,r\n0,0\n1,1\n"), "t.csv:3: a lens table needs at least 3 rows, found 2");
  EXPECT_EQ(ErrorOf("h,p\n0,0\n1,-100\n2,1\n", TableColumns::kPercent),
            "t.csv:3: distortion -100 % would put the point behind the axis");
}

TEST(LensTable, ReportsAMissingFile) {
  try {
    ReadLensTable("/nonexistent/lens.csv", TableColumns::kRealHeight);
    FAIL() << "no error";
  } catch (const LensTableError& error) {
    EXPECT_EQ(std::string(error.what()), "/nonexistent/lens.csv: cannot open: No such file or directory");
  }
}

TEST(LensTable, ShippedFileMatchesTheCompiledInCopy) {
  const LensTable file = ReadLensTable(WS_SOURCE_DIR "/config/lenses/theia-my125m-like.csv",
                                       TableColumns::kRealHeight);
  const LensTable compiled = TheiaLikeLensTable();
  EXPECT_EQ(file.ideal, compiled.ideal);
  EXPECT_EQ(file.real, compiled.real);
}

// The shape config/lenses/README.md promises.
TEST(LensTable, ShippedTableHasTheMustacheShape) {
  const LensTable table = TheiaLikeLensTable();
  const std::vector<double> d = TableDistortion(table);
  ASSERT_EQ(d.size(), 35u);
  EXPECT_EQ(table.ideal.front(), 0.0);
  EXPECT_NEAR(table.ideal.back(), 3.4, 1e-12);
  EXPECT_GT(table.real.back(), 3.0);  // covers the sensor's half-diagonal
  size_t peak = 0;
  for (size_t i = 0; i < d.size(); ++i)
    if (d[i] > d[peak]) peak = i;
  EXPECT_GT(d[peak], 0.02);
  EXPECT_LT(d[peak], 0.03);
  EXPECT_NEAR(table.ideal[peak], 1.15, 0.2);
  for (size_t i = peak + 1; i < d.size(); ++i) EXPECT_LT(d[i], d[i - 1]) << "row " << i;
  EXPECT_LT(d.back(), -0.05);
  EXPECT_LT(std::abs(d[0]), 1e-4);
}

}  // namespace
}  // namespace ws
