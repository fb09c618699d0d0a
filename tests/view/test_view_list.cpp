// The page's list of views: a thumbnail for every view whose frame had a
// board, whatever the page was shown; each update the whole list and its
// change from the one before, the change as small as what changed.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lcm_io/image_codec.h"
#include "view/blob_store.h"
#include "view/view_list.h"

namespace {

using nlohmann::json;
using ws::view::BlobStore;
using ws::view::ViewList;

widestereo::stereo_frame_t Frame(int64_t id, ws::Compression compression = ws::Compression::png) {
  cv::Mat image(960, 1280, CV_8UC1, cv::Scalar(40));
  cv::rectangle(image, {100, 100, 300, 200}, cv::Scalar(220), cv::FILLED);
  widestereo::stereo_frame_t frame{};
  frame.frame_id = id;
  frame.utime = 1000 * id;
  frame.left = ws::MatToImage(image, frame.utime, compression);
  frame.right = ws::MatToImage(image, frame.utime, compression);
  return frame;
}

widestereo::stereo_corners_t Corners(int64_t id, int left, int right) {
  widestereo::stereo_corners_t corners{};
  corners.frame_id = id;
  corners.utime = 1000 * id;
  corners.left.n = left;
  corners.right.n = right;
  return corners;
}

widestereo::calibration_view_t View(int64_t id, double rms = -1) {
  widestereo::calibration_view_t view{};
  view.frame_id = id;
  view.frame_utime = 1000 * id;
  view.left_corners = view.right_corners = 54;
  for (int k = 0; k < 4; ++k)  // an outline's pixels as a board gives them: no round numbers
    for (int c = 0; c < 2; ++c) view.left_outline[k][c] = view.right_outline[k][c] = 101.37f * float(k + c + 1) + 0.61f * float(id);
  view.left_rms = view.right_rms = rms;
  return view;
}

widestereo::calibration_views_t Views(const std::vector<widestereo::calibration_view_t>& list) {
  widestereo::calibration_views_t views{};
  views.image_width[0] = views.image_width[1] = 1280;
  views.image_height[0] = views.image_height[1] = 960;
  views.views = list;
  views.nviews = int32_t(list.size());
  return views;
}

TEST(ViewList, EveryViewWhoseFrameHadABoardGetsAThumbnailOfTheSideThatSawIt) {
  BlobStore blobs;
  ViewList list(blobs);
  list.Found(ws::ThumbnailFrame(Frame(1), Corners(1, 54, 54)));
  list.Found(ws::ThumbnailFrame(Frame(2, ws::Compression::jpeg), Corners(2, 0, 54)));  // no thumbnail of frame 3
  const auto update = list.Event(Views({View(1), View(2), View(3)}));
  ASSERT_TRUE(update);
  const json whole = json::parse(update->whole);
  ASSERT_EQ(whole["views"].size(), 3u);
  EXPECT_EQ(whole["views"][0]["frame_id"], 3) << "newest first";
  EXPECT_TRUE(whole["views"][0]["thumbnail"].is_null());
  for (int i : {1, 2}) {
    const auto blob = blobs.Get(std::stoll(whole["views"][i]["thumbnail"].get<std::string>().substr(5)));
    ASSERT_TRUE(blob);
    const cv::Mat thumbnail = cv::imdecode(blob->bytes, cv::IMREAD_GRAYSCALE);
    EXPECT_EQ(thumbnail.size(), cv::Size(ws::kThumbnailWidth, 96));
    EXPECT_GT(thumbnail.at<uint8_t>(20, 20), 150) << "the image's bright square, scaled";
    EXPECT_LT(thumbnail.at<uint8_t>(80, 110), 90);
  }
}

TEST(ViewList, EachUpdateCarriesOnlyWhatChangedBesideTheWholeList) {
  BlobStore blobs;
  ViewList list(blobs);
  std::vector<widestereo::calibration_view_t> views;
  for (int id = 0; id < 300; ++id) views.push_back(View(id));
  const auto first = list.Event(Views(views));
  ASSERT_TRUE(first);
  EXPECT_FALSE(list.Event(Views(views))) << "nothing changed: nothing sent";

  list.Found(ws::ThumbnailFrame(Frame(300), Corners(300, 54, 54)));
  views.push_back(View(300));
  views.erase(views.begin() + 7);
  const auto second = list.Event(Views(views));
  ASSERT_TRUE(second);
  const json change = json::parse(second->change);
  ASSERT_EQ(change["put"].size(), 1u);
  EXPECT_EQ(change["put"][0]["frame_id"], 300);
  EXPECT_TRUE(change["put"][0]["thumbnail"].is_string());
  EXPECT_EQ(change["gone"], json::array({json::array({7, 7000})}));
  EXPECT_EQ(json::parse(second->whole)["views"].size(), 300u);
  EXPECT_LT(second->change.size() * 50, second->whole.size()) << second->change.size() << " vs " << second->whole.size();
  RecordProperty("whole_bytes", int(second->whole.size()));  // of 300 views
  RecordProperty("change_bytes", int(second->change.size()));  // one view in, one out

  for (auto& view : views) view.left_rms = view.right_rms = 0.2519372;  // a solve: every view changed
  auto solved = Views(views);
  solved.solve_utime = 5;
  const json all = json::parse(list.Event(solved)->change);
  EXPECT_EQ(all["put"].size(), 300u);
  EXPECT_EQ(all["solve_utime"], 5);
  RecordProperty("solve_change_bytes", int(all.dump().size()));  // every view put
}

TEST(ViewList, ThumbnailsWaitingForTheirViewAreBounded) {
  BlobStore blobs;
  ViewList list(blobs);
  const int64_t made = int64_t(ws::view::kCandidatesKept) + 5;
  for (int64_t id = 0; id < made; ++id)
    list.Found(ws::ThumbnailFrame(Frame(id, ws::Compression::none), Corners(id, 54, 0)));
  const json whole = json::parse(list.Event(Views({View(0), View(made - 1)}))->whole);
  EXPECT_TRUE(whole["views"][0]["thumbnail"].is_string()) << "the newest candidate is kept";
  EXPECT_TRUE(whole["views"][1]["thumbnail"].is_null()) << "the oldest is forgotten";
}

TEST(ViewList, AFrameThatCannotBeDecodedMakesNoThumbnail) {
  BlobStore blobs;
  ViewList list(blobs);
  auto frame = Frame(1);
  frame.left.data.resize(frame.left.data.size() / 2);  // a payload cut short
  frame.left.size = int32_t(frame.left.data.size());
  EXPECT_THROW(list.Found(frame), ws::DecodeError);
  EXPECT_TRUE(json::parse(list.Event(Views({View(1)}))->whole)["views"][0]["thumbnail"].is_null());
}

}  // namespace
