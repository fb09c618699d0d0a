// Which views the open pages show: a stream joins with its view (both when
// it names none) and leaves; a view is watched while any stream shows it.
#include <gtest/gtest.h>

#include <stdexcept>

#include "view/audience.h"

namespace {

using ws::view::Audience;
using ws::view::PageView;

TEST(Audience, AViewIsWatchedWhileAnyStreamShowsIt) {
  Audience audience;
  EXPECT_FALSE(audience.Watching(PageView::kCalibration));
  EXPECT_FALSE(audience.Watching(PageView::kDepth));

  const Audience::Views depth = Audience::Parse("depth"), both = Audience::Parse("");
  audience.Join(depth);
  EXPECT_FALSE(audience.Watching(PageView::kCalibration));
  EXPECT_TRUE(audience.Watching(PageView::kDepth));
  audience.Join(both);
  EXPECT_TRUE(audience.Watching(PageView::kCalibration));
  audience.Leave(depth);
  EXPECT_TRUE(audience.Watching(PageView::kDepth));  // the other stream still shows it
  audience.Leave(both);
  EXPECT_FALSE(audience.Watching(PageView::kCalibration));
  EXPECT_FALSE(audience.Watching(PageView::kDepth));

  audience.Join(Audience::Parse("calibration"));
  EXPECT_TRUE(audience.Watching(PageView::kCalibration));
  EXPECT_FALSE(audience.Watching(PageView::kDepth));
  // A set of views is watched while any one of them is.
  EXPECT_FALSE(audience.Watching(depth));
  EXPECT_TRUE(audience.Watching(both));
}

TEST(Audience, AnotherViewNameIsRefused) {
  EXPECT_THROW(Audience::Parse("everything"), std::invalid_argument);
  EXPECT_THROW(Audience::Parse("Depth"), std::invalid_argument);
}

}  // namespace
