#include "view/view_list.h"

#include <set>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "view/page_events.h"

namespace ws::view {
namespace {

using nlohmann::json;

json Outline(const float (&outline)[4][2]) {
  json points = json::array();
  for (const auto& p : outline) points.push_back({p[0], p[1]});
  return points;
}

json Rms(double rms) { return rms < 0 ? json(nullptr) : json(rms); }

}  // namespace

ViewList::ViewList(BlobStore& blobs, FrameImage frame_image) : blobs_(blobs), frame_image_(std::move(frame_image)) {}

std::string ViewList::Thumbnail(const Key& key, const std::string& side) {
  if (const auto found = thumbnails_.find(key); found != thumbnails_.end()) return found->second;
  const auto jpeg = frame_image_(key.first, key.second, side);
  if (!jpeg) return "";
  const cv::Mat image = cv::imdecode(jpeg->bytes, cv::IMREAD_COLOR);
  if (image.empty()) return "";
  const std::string src = blobs_.Put("thumbnail", kThumbnailsKept, Jpeg(image, kThumbnailWidth));
  thumbnails_[key] = src;
  made_.emplace_back(key, src);
  if (made_.size() > kThumbnailsKept) {  // the store has just forgotten it
    const auto& [oldest, oldest_src] = made_.front();
    if (const auto found = thumbnails_.find(oldest); found != thumbnails_.end() && found->second == oldest_src)
      thumbnails_.erase(found);
    made_.pop_front();
  }
  return src;
}

std::optional<std::string> ViewList::Event(const widestereo::calibration_views_t& views) {
  json list = json::array();
  std::set<Key> held;
  // Newest first: those are the ones whose frames may still be at hand.
  for (auto view = views.views.rbegin(); view != views.views.rend(); ++view) {
    const Key key{view->frame_id, view->frame_utime};
    held.insert(key);
    const std::string thumbnail = Thumbnail(key, view->left_corners > 0 ? "left" : "right");  // as the page draws
    list.push_back({{"frame_id", view->frame_id},
                    {"utime", view->frame_utime},
                    {"left_corners", view->left_corners},
                    {"right_corners", view->right_corners},
                    {"left_outline", Outline(view->left_outline)},
                    {"right_outline", Outline(view->right_outline)},
                    {"left_rms", Rms(view->left_rms)},
                    {"right_rms", Rms(view->right_rms)},
                    {"thumbnail", thumbnail.empty() ? json(nullptr) : json(thumbnail)}});
  }
  for (auto it = thumbnails_.begin(); it != thumbnails_.end();)  // removed, reset: not shown again
    it = held.count(it->first) ? std::next(it) : thumbnails_.erase(it);
  std::string event = json{{"solve_utime", views.solve_utime},
                           {"width", {views.image_width[0], views.image_width[1]}},
                           {"height", {views.image_height[0], views.image_height[1]}},
                           {"views", list}}
                          .dump();
  if (event == last_) return std::nullopt;
  last_ = event;
  return event;
}

}  // namespace ws::view
